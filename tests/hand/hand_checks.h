#pragma once
// Checks of a hand description's grasping semantics, shared by the shipped-hand and the
// dataset-hand tests: the GCP points from the palm into the grasp, actors close towards it.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cordgrasp/core/geometry_points.h"
#include "cordgrasp/core/hand_fingers.h"
#include "cordgrasp/core/hand_model.h"
#include "cordgrasp/core/kinematics.h"

namespace cordgrasp::test {

/// q with every joint of `actor` advanced by step·speed, couplings and limits applied.
inline Eigen::VectorXd advance_actor(const HandModel& hand, const Actor& actor,
                                     const Eigen::VectorXd& q, double step) {
  Eigen::VectorXd out = q;
  for (const auto& e : actor.joints) out[e.joint] += step * e.direction_speed;
  return clamp_to_limits(hand, apply_couplings(hand, clamp_to_limits(hand, out)));
}

/// Every actor, advanced from the preshape by `step` (joint units per unit of speed), moves each
/// of its fingertips at least `min_gain_m` closer to the GCP's z axis, and closer to the GCP.
inline void expect_actors_close_towards_gcp(const HandModel& hand, double step, double min_gain_m) {
  const Eigen::VectorXd q0 = apply_couplings(hand, hand.preshape);
  const auto X0 = link_poses(hand, q0);
  const Eigen::Isometry3d X_GW = gcp_pose(hand, X0).inverse();
  const std::vector<Finger> fingers = hand_fingers(hand);
  ASSERT_FALSE(fingers.empty()) << hand.name;
  for (size_t a = 0; a < hand.actors.size(); ++a) {
    const Actor& actor = hand.actors[a];
    const auto X1 = link_poses(hand, advance_actor(hand, actor, q0, step));
    int n = 0;
    for (const Finger& f : fingers) {
      if (f.actor != static_cast<int>(a) || f.tip_link < 0) continue;
      ++n;
      const Eigen::Vector3d t0 = X_GW * (X0[f.tip_link] * f.p_tip_L);
      const Eigen::Vector3d t1 = X_GW * (X1[f.tip_link] * f.p_tip_L);
      EXPECT_LT(t1.head<2>().norm(), t0.head<2>().norm() - min_gain_m)
          << hand.name << " actor '" << actor.name << "' tip on '" << hand.links[f.tip_link].name
          << "' does not close towards the GCP axis: " << t0.head<2>().norm() << " -> "
          << t1.head<2>().norm() << " m";
      EXPECT_LT(t1.norm(), t0.norm())
          << hand.name << " actor '" << actor.name << "' tip moves away from the GCP";
    }
    EXPECT_GT(n, 0) << hand.name << " actor '" << actor.name << "' moves no geometry";
  }
}

/// In preshape, in the GCP frame: the geometry no actor moves (the palm) lies behind the GCP
/// (z < 0), and the thumb tip and the other fingertips lie on opposite sides of the GCP axis.
inline void expect_gcp_points_into_grasp(const HandModel& hand) {
  const Eigen::VectorXd q0 = apply_couplings(hand, hand.preshape);
  const auto X0 = link_poses(hand, q0);
  const Eigen::Isometry3d X_GW = gcp_pose(hand, X0).inverse();
  const std::vector<Finger> fingers = hand_fingers(hand);
  std::vector<bool> moved(hand.links.size(), false);
  for (const Finger& f : fingers)
    for (int l : f.links) moved[l] = true;
  Eigen::Vector3d palm = Eigen::Vector3d::Zero();
  int n = 0;
  std::vector<Eigen::Vector3d> pts;
  for (size_t l = 0; l < hand.links.size(); ++l) {
    if (moved[l]) continue;
    pts.clear();
    append_collision_points(hand.links[l], pts);
    for (const auto& p : pts) {
      palm += X_GW * (X0[l] * p);
      ++n;
    }
  }
  ASSERT_GT(n, 0) << hand.name << " has no static geometry";
  palm /= n;
  EXPECT_LT(palm.z(), 0.0) << hand.name << ": the palm is not behind the GCP (+z points into it)";

  Eigen::Vector2d thumb = Eigen::Vector2d::Zero();
  Eigen::Vector2d others = Eigen::Vector2d::Zero();
  int n_thumb = 0, n_others = 0;
  for (const Finger& f : fingers) {
    if (f.tip_link < 0) continue;
    const Eigen::Vector2d xy = (X_GW * (X0[f.tip_link] * f.p_tip_L)).head<2>();
    (f.is_thumb ? thumb : others) += xy;
    (f.is_thumb ? n_thumb : n_others) += 1;
  }
  ASSERT_EQ(n_thumb, 1) << hand.name << ": exactly one finger should hold the thumb links";
  ASSERT_GT(n_others, 0) << hand.name;
  others /= n_others;
  EXPECT_LT(thumb.dot(others), 0.0)
      << hand.name << ": thumb tip and fingertips are not on opposite sides of the GCP axis";
}

}  // namespace cordgrasp::test
