#include "cordgrasp/core/grasp_diversity.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace cordgrasp {

GraspPoseDistance grasp_pose_distance(const Grasp& a, const Grasp& b) {
  GraspPoseDistance d;
  d.gcp_m = (a.X_OG.translation() - b.X_OG.translation()).norm();
  const Eigen::AngleAxisd turn(a.X_OB.linear().transpose() * b.X_OB.linear());
  d.hand_turn_rad = std::abs(turn.angle());
  return d;
}

double min_gcp_distance_m(const DiversityParams& p, double object_radius_m) {
  return std::max(p.min_gcp_distance_m, p.min_gcp_distance_per_radius * object_radius_m);
}

bool grasps_differ(const Grasp& a, const Grasp& b, const DiversityParams& p,
                   double object_radius_m) {
  const GraspPoseDistance d = grasp_pose_distance(a, b);
  return d.gcp_m >= min_gcp_distance_m(p, object_radius_m) ||
         d.hand_turn_rad >= p.min_hand_turn_deg * M_PI / 180.0;
}

bool differs_from_all(const Grasp& g, const std::vector<Grasp>& accepted,
                      const DiversityParams& p, double object_radius_m) {
  return std::all_of(accepted.begin(), accepted.end(), [&](const Grasp& a) {
    return grasps_differ(a, g, p, object_radius_m);
  });
}

}  // namespace cordgrasp
