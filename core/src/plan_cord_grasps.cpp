#include "cordgrasp/core/plan_cord_grasps.h"

#include <algorithm>
#include <future>
#include <numeric>
#include <optional>

#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/core/palm_width.h"
#include "cordgrasp/core/scan_cord_set.h"
#include "cordgrasp/core/segment_mesh_hits.h"
#include "plan_internal.h"

namespace cordgrasp {

double approach_travel_m(const Mesh& mesh, const GraspRegion& region) {
  const Eigen::Vector3d c = vertex_mean(mesh);
  return approach_travel_m(mesh, region, c, bounding_radius(mesh, c), nullptr);
}

double approach_travel_m(const Mesh& mesh, const GraspRegion& region,
                         const Eigen::Vector3d& vertex_mean_O, double radius_m,
                         const MeshBvh* bvh) {
  const Eigen::Vector3d v = region.p_m - region.p1;
  const double fallback = v.norm();
  if (fallback <= 0.0) return 0.0;
  const Eigen::Vector3d z = v / fallback;
  const double reach = (region.p1 - vertex_mean_O).norm() + radius_m;
  // First surface hit along the approach (docs/algorithm.md §7.2).
  const Eigen::Vector3d end = region.p1 + reach * z;
  const auto hits =
      bvh ? segment_mesh_hits(*bvh, region.p1, end) : segment_mesh_hits(mesh, region.p1, end);
  return hits.empty() ? fallback : hits.front().t * reach;
}

PlanResult plan_cord_fallback_grasps(const Mesh& mesh, const HandModel& hand,
                                     HandObjectCollider& collider, const PlanParams& params,
                                     const CancelToken& cancel, const PlanContext* context) {
  return internal::plan_sampled_grasps(mesh, hand, collider, params,
                                       internal::SampledApproach::kToMiddle, cancel, context);
}

PlanResult plan_cord_grasps_from_regions(const Mesh& mesh, const HandModel& hand,
                                         HandObjectCollider& collider,
                                         const std::vector<GraspRegion>& regions,
                                         const PlanParams& params, double exploration_s,
                                         const std::vector<int>* order_in,
                                         const CancelToken& cancel, const PlanContext* context) {
  using internal::seconds_since;
  const auto start = std::chrono::steady_clock::now();
  PlanResult result;
  PlanStats& stats = result.stats;
  stats.exploration_s = exploration_s;
  stats.regions = static_cast<int>(regions.size());
  std::optional<PlanContext> own;
  if (!context) own = internal::make_plan_context(mesh, hand, collider, params, stats);
  const PlanContext& ctx = context ? *context : *own;
  const Eigen::Vector3d center_O = vertex_mean(mesh);
  const std::shared_ptr<const MeshBvh> bvh = collider.object_bvh();

  std::vector<size_t> order;
  if (order_in) {
    for (int i : *order_in)
      if (i >= 0 && static_cast<size_t>(i) < regions.size())
        order.push_back(static_cast<size_t>(i));
  } else {
    order.resize(regions.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return regions[a].chi_m2 < regions[b].chi_m2; });
  }
  const int wanted = std::max(1, params.grasps);
  for (size_t rank = 0; rank < order.size(); ++rank) {
    if (static_cast<int>(result.grasps.size()) >= wanted) break;
    if (exploration_s + seconds_since(start) > params.time_limit_s) {
      stats.timed_out = true;
      break;
    }
    if (stats.attempts >= params.max_attempts) break;
    if (cancel.cancelled()) {
      stats.interrupted = true;
      break;
    }
    const GraspRegion& region = regions[order[rank]];
    ++stats.regions_processed;
    const double travel = approach_travel_m(mesh, region, center_O, ctx.radius_m, bvh.get());
    for (int roll = 0; roll < (params.roll_retry ? 2 : 1); ++roll) {
      if (stats.attempts >= params.max_attempts) break;
      const Eigen::Isometry3d X_OG = gcp_pose_for_region(region, ctx.setup.R_GH, roll == 1);
      Grasp grasp;
      if (!internal::attempt_grasp(hand, collider, ctx, params, X_OG, travel, stats, grasp))
        continue;
      if (!differs_from_all(grasp, result.grasps, params.diversity, ctx.radius_m)) {
        ++stats.similar;
        continue;
      }
      grasp.region_rank = static_cast<int>(rank);
      grasp.chi_m2 = region.chi_m2;
      grasp.region = region;
      grasp.times.exploration_s = exploration_s;
      if (!stats.first_force_closure_s)
        stats.first_force_closure_s = exploration_s + seconds_since(start);
      result.grasps.push_back(std::move(grasp));
      break;
    }
  }
  if (static_cast<int>(result.grasps.size()) < wanted) {
    if (exploration_s + seconds_since(start) > params.time_limit_s) stats.timed_out = true;
    if (stats.attempts >= params.max_attempts) stats.attempt_budget_reached = true;
  }
  stats.total_s = exploration_s + seconds_since(start);
  return result;
}

std::vector<int> cord_region_order(const std::vector<GraspRegion>& regions, double palm_width_m,
                                   const CordParams& cord) {
  std::vector<int> order(regions.size());
  std::iota(order.begin(), order.end(), 0);
  // Sort key before χ: 1 for a set shrunk below the palm width; under kFallback the number of
  // missed (empty) cords, so that the sets closest to the paper's full sets come first.
  std::vector<int> shrunk(regions.size(), 0);
  for (size_t i = 0; i < regions.size(); ++i) {
    const GraspRegion& g = regions[i];
    shrunk[i] = g.n < cords_per_side(g.p1, g.p2, g.p3, g.p_m, palm_width_m, cord) ? 1 : 0;
    if (cord.side_cord_policy == SideCordPolicy::kFallback)
      shrunk[i] = side_cords_missed(g);  // 0 = every cord touches the object
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    if (shrunk[static_cast<size_t>(a)] != shrunk[static_cast<size_t>(b)])
      return shrunk[static_cast<size_t>(a)] < shrunk[static_cast<size_t>(b)];
    return regions[static_cast<size_t>(a)].chi_m2 < regions[static_cast<size_t>(b)].chi_m2;
  });
  return order;
}

PlanResult plan_cord_grasps(const Mesh& mesh, const HandModel& hand, HandObjectCollider& collider,
                            const CordParams& cord, const PlanParams& params,
                            ExplorationStats* exploration, const CancelToken& cancel,
                            int threads) {
  const auto start = std::chrono::steady_clock::now();
  CordParams explore = cord;
  if (explore.time_limit_s <= 0.0 || explore.time_limit_s > params.time_limit_s)
    explore.time_limit_s = params.time_limit_s;
  const double w_palm = palm_width(hand);
  // With threads to spare, the object's constants (a scan's solid volume, principal axes)
  // are derived beside the exploration.
  double object_s = 0.0;
  std::future<PlanContext> object;
  if (threads > 1)
    object = std::async(std::launch::async, [&]() {
      const auto t0 = std::chrono::steady_clock::now();
      PlanContext ctx = object_plan_context(mesh, params, collider.object_bvh());
      object_s = internal::seconds_since(t0);
      return ctx;
    });
  ExplorationStats explored;
  const std::vector<GraspRegion> regions =
      explore_cords(mesh, w_palm, explore, &explored, collider.object_bvh(), threads);
  if (exploration) *exploration = explored;
  const std::vector<int> order = cord_region_order(regions, w_palm, explore);
  const double explored_s = internal::seconds_since(start);
  std::optional<PlanContext> ctx;
  double hand_s = 0.0;
  if (object.valid()) {
    ctx = object.get();
    const auto t0 = std::chrono::steady_clock::now();
    ctx->setup = prepare_hand(hand, collider);
    hand_s = internal::seconds_since(t0);
  } else {
    PlanStats setup;
    ctx = internal::make_plan_context(mesh, hand, collider, params, setup);
    hand_s = setup.setup_s;
  }
  const double after_exploration_s = internal::seconds_since(start) - explored_s;
  PlanResult result = plan_cord_grasps_from_regions(mesh, hand, collider, regions, params,
                                                    explored_s, &order, cancel, &*ctx);
  // The set-up's own time, partly beside the exploration; the wall time after the exploration
  // (the wait for it, the set-up's part) counts in the totals.
  PlanStats& stats = result.stats;
  stats.setup_s = object_s + hand_s;
  stats.total_s += after_exploration_s;
  if (stats.first_force_closure_s) *stats.first_force_closure_s += after_exploration_s;
  const int wanted = std::max(1, params.grasps);
  if (static_cast<int>(result.grasps.size()) < wanted && params.fallback_attempts > 0 &&
      !stats.timed_out && !stats.interrupted) {
    // Regions or attempts spent: sampled surface points (plan_cord_fallback_grasps), as many
    // more.
    const int before = stats.attempts;
    stats.attempt_budget_reached = false;
    internal::sample_surface_grasps(mesh, hand, collider, *ctx, params,
                                    internal::SampledApproach::kToMiddle, params.fallback_attempts,
                                    start, 0.0, cancel, result);
    stats.sampled_attempts = stats.attempts - before;
    stats.total_s = internal::seconds_since(start);
  }
  if (explored.hit_time_limit && static_cast<int>(result.grasps.size()) < params.grasps)
    stats.timed_out = true;  // fewer regions than a faster machine would have found
  return result;
}

}  // namespace cordgrasp
