#pragma once
// When two grasps of one object count as different (docs/algorithm.md §10): the planners
// return, and validated planning accepts, only grasps that differ pairwise.
#include <vector>

#include "cordgrasp/core/grasp.h"
#include "cordgrasp/core/serialize.h"

namespace cordgrasp {

/// Two grasps differ when their GCPs are at least max(min_gcp_distance_m,
/// min_gcp_distance_per_radius × the object's bounding radius) apart, or their hand
/// orientations at least min_hand_turn_deg apart. All 0: every grasp differs (no rule).
struct DiversityParams {
  double min_gcp_distance_m = 0.01;          ///< [m]
  double min_gcp_distance_per_radius = 0.25;  ///< [-]
  double min_hand_turn_deg = 20.0;            ///< [deg]

  /// Visits every field in declaration order (core/serialize.h).
  template <typename Archive>
  void Serialize(Archive* a) {
    visit_fields(a, CORDGRASP_NVP(min_gcp_distance_m), CORDGRASP_NVP(min_gcp_distance_per_radius),
                 CORDGRASP_NVP(min_hand_turn_deg));
  }
};

/// GCP distance of two grasps [m] and the angle between their hand orientations [rad].
struct GraspPoseDistance {
  double gcp_m = 0.0;
  double hand_turn_rad = 0.0;
};

/// Pose distance of grasps a and b (X_OG translations; rotation from X_OB_a to X_OB_b).
GraspPoseDistance grasp_pose_distance(const Grasp& a, const Grasp& b);

/// GCP distance at which two grasps of an object of bounding radius `object_radius_m` differ
/// [m].
double min_gcp_distance_m(const DiversityParams& p, double object_radius_m);

/// True when grasps a and b of an object of bounding radius `object_radius_m` differ.
bool grasps_differ(const Grasp& a, const Grasp& b, const DiversityParams& p,
                   double object_radius_m);

/// True when `g` differs from every grasp of `accepted`.
bool differs_from_all(const Grasp& g, const std::vector<Grasp>& accepted,
                      const DiversityParams& p, double object_radius_m);

}  // namespace cordgrasp
