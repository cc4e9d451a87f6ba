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
  /// Each fingertip must come at least this much nearer the GCP z axis in its closing sweep [m].
  double min_closing_m = 0.003;
  /// The closing sweep: the actor advances in steps of sweep_step (the finger stage's step,
  /// docs/algorithm.md §7.4) until its revolute joints have turned max_curl_rad in all, or by
  /// closing_range [rad, or m per unit of speed].
  double sweep_step = 0.02;
  double max_curl_rad = 1.5707963267948966;  // 90°
  double closing_range = 1.5707963267948966;
};

/// One line per broken convention, empty when the hand follows them all, in preshape:
/// the palm (geometry no actor moves) lies at GCP z < 0; exactly one finger holds the thumb
/// links and its tip and the other fingertips lie on opposite sides of the GCP z axis; in each
/// actor's closing sweep every fingertip of it comes >= min_closing_m nearer the GCP axis, or
/// as much ahead along it without leaving it, and advanced by closing_step it is nearer the
/// GCP; the palm normal (when given) has the GCP in front of the palm's centroid and no
/// fingertip, advanced by closing_step, moved backwards to behind it.
std::vector<std::string> check_hand_conventions(const HandModel& hand,
                                                const HandConventionParams& params = {});

/// q with every joint of `actor` advanced by step · speed, couplings and limits applied.
Eigen::VectorXd advance_actor(const HandModel& hand, const Actor& actor, const Eigen::VectorXd& q,
                              double step);

}  // namespace cordgrasp
