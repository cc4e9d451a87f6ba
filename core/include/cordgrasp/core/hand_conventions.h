#pragma once
// The grasping conventions a hand description must follow (docs/hand-description.md): the GCP
// points from the palm into the grasp, actors close towards it, the palm normal points from the
// palm towards the fingers' closing region.
#include <string>
#include <vector>

#include "cordgrasp/core/hand_model.h"

namespace cordgrasp {

/// Thresholds of check_hand_conventions.
struct HandConventionParams {
  /// Actor motion from the preshape for the closing checks [rad, or m per unit of speed]:
  /// 0.3 = 15 finger-stage steps of 0.02 (docs/algorithm.md §7.4).
  double closing_step = 0.3;
  /// Each fingertip must come at least this much nearer the GCP z axis over closing_step [m].
  double min_closing_m = 0.003;
};

/// One line per broken convention, empty when the hand follows them all, in preshape:
/// the palm (geometry no actor moves) lies at GCP z < 0; exactly one finger holds the thumb
/// links and its tip and the other fingertips lie on opposite sides of the GCP z axis; every
/// actor advanced by closing_step brings each of its fingertips >= min_closing_m nearer the GCP
/// axis and nearer the GCP; the palm normal (when given) has the GCP and the closed fingertips'
/// centroid in front of the palm's centroid.
std::vector<std::string> check_hand_conventions(const HandModel& hand,
                                                const HandConventionParams& params = {});

/// q with every joint of `actor` advanced by step · speed, couplings and limits applied.
Eigen::VectorXd advance_actor(const HandModel& hand, const Actor& actor, const Eigen::VectorXd& q,
                              double step);

}  // namespace cordgrasp
