#include "cordgrasp/core/plan_cord_grasps.h"

#include <algorithm>
#include <numeric>

#include "cordgrasp/core/mesh_properties.h"
#include "mesh_ray_internal.h"
#include "plan_internal.h"

namespace cordgrasp {

double approach_travel_m(const Mesh& mesh, const GraspRegion& region) {
  const Eigen::Vector3d v = region.p_m - region.p1;
  const double fallback = v.norm();
  if (fallback <= 0.0) return 0.0;
  const Eigen::Vector3d z = v / fallback;
  const Eigen::Vector3d c = vertex_mean(mesh);
  const double reach = (region.p1 - c).norm() + bounding_radius(mesh, c);
  const auto hits = internal::segment_hit_params(mesh, region.p1, region.p1 + reach * z);
  return hits.empty() ? fallback : hits.front() * reach;
}

PlanResult plan_cord_grasps_from_regions(const Mesh& mesh, const HandModel& hand,
                                         HandObjectCollider& collider,
                                         const std::vector<GraspRegion>& regions,
                                         const PlanParams& params, double exploration_s) {
  using internal::seconds_since;
  const auto start = std::chrono::steady_clock::now();
  PlanResult result;
  PlanStats& stats = result.stats;
  stats.exploration_s = exploration_s;
  stats.regions = static_cast<int>(regions.size());
  const internal::PlanContext ctx =
      internal::make_plan_context(mesh, hand, collider, params, stats);

  std::vector<size_t> order(regions.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return regions[a].chi_m2 < regions[b].chi_m2; });
  const int wanted = std::max(1, params.grasps);
  for (size_t rank = 0; rank < order.size(); ++rank) {
    if (static_cast<int>(result.grasps.size()) >= wanted) break;
    if (exploration_s + seconds_since(start) > params.time_limit_s) {
      stats.timed_out = true;
      break;
    }
    const GraspRegion& region = regions[order[rank]];
    ++stats.regions_processed;
    const double travel = approach_travel_m(mesh, region);
    for (int roll = 0; roll < (params.roll_retry ? 2 : 1); ++roll) {
      const Eigen::Isometry3d X_OG = gcp_pose_for_region(region, ctx.setup.R_GH, roll == 1);
      Grasp grasp;
      if (!internal::attempt_grasp(hand, collider, ctx, params, X_OG, travel, stats, grasp))
        continue;
      grasp.region_rank = static_cast<int>(rank);
      grasp.chi_m2 = region.chi_m2;
      grasp.times.exploration_s = exploration_s;
      if (!stats.first_force_closure_s)
        stats.first_force_closure_s = exploration_s + seconds_since(start);
      result.grasps.push_back(std::move(grasp));
      break;
    }
  }
  if (static_cast<int>(result.grasps.size()) < wanted &&
      exploration_s + seconds_since(start) > params.time_limit_s)
    stats.timed_out = true;
  stats.total_s = exploration_s + seconds_since(start);
  return result;
}

}  // namespace cordgrasp
