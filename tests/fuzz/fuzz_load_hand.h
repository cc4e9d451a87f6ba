#pragma once
// Shared by fuzz_urdf and fuzz_hand_yaml: what `cordgrasp info --hand` computes from a hand.
#include <string>

#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/kinematics.h"
#include "cordgrasp/core/palm_width.h"

namespace cordgrasp::fuzz {

/// Loads the hand description at `path`, poses the hand in its preshape (FK, GCP) and
/// measures it (DOF, mass, palm width). @throws what load_hand throws.
inline void load_and_pose_hand(const std::string& path) {
  const HandModel hand = load_hand(path);
  const Eigen::VectorXd q = apply_couplings(hand, hand.preshape);
  gcp_pose(hand, link_poses(hand, q));
  degrees_of_freedom(hand);
  total_mass(hand);
  palm_width(hand);
}

}  // namespace cordgrasp::fuzz
