#include "cordgrasp/core/plan_generic_grasps.h"

#include <cmath>
#include <optional>
#include <random>

#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/core/segment_mesh_hits.h"
#include "plan_internal.h"

namespace cordgrasp {

Eigen::Vector3d outward_face_normal(const Mesh& mesh, int tri, const Eigen::Vector3d& p_O) {
  const Eigen::Vector3d c = vertex_mean(mesh);
  return outward_face_normal(mesh, tri, p_O, c, bounding_radius(mesh, c), nullptr);
}

Eigen::Vector3d outward_face_normal(const Mesh& mesh, int tri, const Eigen::Vector3d& p_O,
                                    const Eigen::Vector3d& vertex_mean_O, double radius_m,
                                    const MeshBvh* bvh) {
  const Eigen::Vector3i& t = mesh.triangles.at(static_cast<size_t>(tri));
  const Eigen::Vector3d& a = mesh.vertices[t[0]];
  Eigen::Vector3d n = (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a);
  if (n.norm() <= 0.0) return Eigen::Vector3d::UnitZ();
  n.normalize();
  const double reach = 2.0 * radius_m + (p_O - vertex_mean_O).norm() + 1.0;
  // Start just off the surface so the ray does not count its own triangle.
  const double lift = 1e-7 * reach;
  const Eigen::Vector3d from = p_O + lift * n, to = p_O + reach * n;
  const auto hits = bvh ? segment_mesh_hits(*bvh, from, to) : segment_mesh_hits(mesh, from, to);
  return hits.size() % 2 == 1 ? Eigen::Vector3d(-n) : n;
}

PlanResult plan_generic_grasps(const Mesh& mesh, const HandModel& hand,
                               HandObjectCollider& collider, const PlanParams& params,
                               const CancelToken& cancel, const PlanContext* context) {
  return internal::plan_sampled_grasps(mesh, hand, collider, params,
                                       internal::SampledApproach::kNone, cancel, context);
}

namespace internal {

PlanResult plan_sampled_grasps(const Mesh& mesh, const HandModel& hand,
                               HandObjectCollider& collider, const PlanParams& params,
                               SampledApproach approach, const CancelToken& cancel,
                               const PlanContext* context) {
  const auto start = std::chrono::steady_clock::now();
  PlanResult result;
  std::optional<PlanContext> own;
  if (!context) own = make_plan_context(mesh, hand, collider, params, result.stats);
  sample_surface_grasps(mesh, hand, collider, context ? *context : *own, params, approach,
                        params.max_attempts, start, 0.0, cancel, result);
  result.stats.total_s = seconds_since(start);
  return result;
}

double thickness_m(const Mesh& mesh, const MeshBvh* bvh, const Eigen::Vector3d& p_O,
                   const Eigen::Vector3d& z_O, double reach_m) {
  // Start just off the surface so the ray does not count the point's own triangle.
  const Eigen::Vector3d from = p_O + 1e-7 * reach_m * z_O, to = p_O + reach_m * z_O;
  const auto hits = bvh ? segment_mesh_hits(*bvh, from, to) : segment_mesh_hits(mesh, from, to);
  return hits.empty() ? 0.0 : (from + hits.front().t * (to - from) - p_O).norm();
}

void sample_surface_grasps(const Mesh& mesh, const HandModel& hand, HandObjectCollider& collider,
                           const PlanContext& ctx, const PlanParams& params,
                           SampledApproach approach, int max_attempts,
                           std::chrono::steady_clock::time_point start, double offset_s,
                           const CancelToken& cancel, PlanResult& result) {
  PlanStats& stats = result.stats;
  // Area-weighted triangle sampling.
  std::vector<double> areas(mesh.triangles.size(), 0.0);
  for (size_t i = 0; i < mesh.triangles.size(); ++i) {
    const Eigen::Vector3i& t = mesh.triangles[i];
    areas[i] = 0.5 * (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                         .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]])
                         .norm();
  }
  std::discrete_distribution<int> pick_triangle(areas.begin(), areas.end());
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::mt19937_64 rng(params.seed);
  const Eigen::Vector3d center_O = vertex_mean(mesh);
  const std::shared_ptr<const MeshBvh> bvh = collider.object_bvh();

  const int wanted = std::max(1, params.grasps);
  const int attempts_end = stats.attempts + std::max(0, max_attempts);
  while (static_cast<int>(result.grasps.size()) < wanted) {
    if (stats.attempts >= attempts_end) {
      stats.attempt_budget_reached = true;
      break;
    }
    if (offset_s + seconds_since(start) > params.time_limit_s) {
      stats.timed_out = true;
      break;
    }
    if (cancel.cancelled()) {
      stats.interrupted = true;
      break;
    }
    const int tri = pick_triangle(rng);
    const Eigen::Vector3i& t = mesh.triangles[static_cast<size_t>(tri)];
    double u = unit(rng), v = unit(rng);
    if (u + v > 1.0) {
      u = 1.0 - u;
      v = 1.0 - v;
    }
    const Eigen::Vector3d p = mesh.vertices[t[0]] +
                              u * (mesh.vertices[t[1]] - mesh.vertices[t[0]]) +
                              v * (mesh.vertices[t[2]] - mesh.vertices[t[0]]);
    const Eigen::Vector3d z = -outward_face_normal(mesh, tri, p, center_O, ctx.radius_m, bvh.get());
    const double roll = 2.0 * M_PI * unit(rng);
    Eigen::Index axis = 0;
    z.cwiseAbs().minCoeff(&axis);
    const Eigen::Vector3d e = Eigen::Vector3d::Unit(axis);
    Eigen::Vector3d x = (e - e.dot(z) * z).normalized();
    x = Eigen::AngleAxisd(roll, z) * x;
    Eigen::Isometry3d X_OG = Eigen::Isometry3d::Identity();
    X_OG.linear().col(0) = x;
    X_OG.linear().col(1) = z.cross(x);
    X_OG.linear().col(2) = z;
    X_OG.translation() = p;
    const double travel =
        approach == SampledApproach::kToMiddle
            ? 0.5 * thickness_m(mesh, bvh.get(), p, z, 2.0 * ctx.radius_m + (p - center_O).norm())
            : 0.0;
    Grasp grasp;
    if (!internal::attempt_grasp(hand, collider, ctx, params, X_OG, travel, stats, grasp)) continue;
    if (!differs_from_all(grasp, result.grasps, params.diversity, ctx.radius_m)) {
      ++stats.similar;
      continue;
    }
    if (!stats.first_force_closure_s) stats.first_force_closure_s = offset_s + seconds_since(start);
    result.grasps.push_back(std::move(grasp));
  }
}

}  // namespace internal

}  // namespace cordgrasp
