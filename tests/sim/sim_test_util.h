#pragma once
// Grasps built in test code for the physics tests.
#include <Eigen/Geometry>

#include "cordgrasp/core/grasp.h"
#include "cordgrasp/core/hand_model.h"
#include "cordgrasp/core/kinematics.h"

namespace cordgrasp::test {

/// GCP at `p_OG` approaching along −z_O from above, x_G = x_O (a parallel gripper's fingers
/// close along ±x_O); joints at `opening` (prismatic joints of the gripper, coupled).
inline Grasp top_down_pinch(const HandModel& hand, const Eigen::Vector3d& p_OG, double opening,
                            double preshape_opening) {
  Grasp g;
  g.X_OG.linear() = Eigen::Vector3d(1, -1, -1).asDiagonal();
  g.X_OG.translation() = p_OG;
  Eigen::VectorXd q = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(hand.joints.size()));
  Eigen::VectorXd q0 = q;
  for (size_t j = 0; j < hand.joints.size(); ++j)
    if (hand.joints[j].type == JointType::kPrismatic && !hand.joints[j].mimic) {
      q[static_cast<Eigen::Index>(j)] = opening;
      q0[static_cast<Eigen::Index>(j)] = preshape_opening;
    }
  g.q = clamp_to_limits(hand, apply_couplings(hand, q));
  g.q_preshape = clamp_to_limits(hand, apply_couplings(hand, q0));
  g.X_OB = root_pose_for_gcp(hand, g.q, g.X_OG);
  return g;
}

}  // namespace cordgrasp::test
