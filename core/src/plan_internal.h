#pragma once
// core-internal helpers shared by plan_cord_grasps and plan_generic_grasps.
#include <chrono>
#include <vector>

#include "cordgrasp/core/cancel_token.h"
#include "cordgrasp/core/grasp_plan.h"
#include "cordgrasp/core/mesh.h"
#include "cordgrasp/core/mesh_bvh.h"
#include "cordgrasp/core/plan_context.h"

namespace cordgrasp::internal {

/// Seconds since `start` (steady clock).
inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// make_plan_context(), timed into stats.setup_s.
PlanContext make_plan_context(const Mesh& mesh, const HandModel& hand, HandObjectCollider& collider,
                              const PlanParams& params, PlanStats& stats);

/// How far outside the surface, along a contact's normal (object → link), the link is looked
/// for: a link that touched the surface from inside lies inside the solid there [m]. Thinner
/// than any finger, well beyond the contact tolerance.
constexpr double kInsideProbeOffsetM = 1e-3;

/// True when a contact's link side (kInsideProbeOffsetM along its normal) lies inside the
/// solid (|winding number| ≥ 0.5): a link that started inside a closed object, or touched a
/// face inside another component, touches the surface from within.
bool touched_from_inside(const WindingNumberTree& solid, const std::vector<Contact>& contacts);

/// Runs the finger stage from X_OG_start, the inside test of its contacts (closed meshes),
/// then the quality check; counts the outcome in `stats`. Returns true and fills `grasp` when
/// the grasp is force-closure.
bool attempt_grasp(const HandModel& hand, HandObjectCollider& collider, const PlanContext& ctx,
                   const PlanParams& params, const Eigen::Isometry3d& X_OG_start,
                   double approach_travel_m, PlanStats& stats, Grasp& grasp);

/// How far a sampled point's hand approaches before it retreats until free.
enum class SampledApproach {
  kNone,      ///< the generic baseline (Simox): the GCP starts on the point and only retreats
  kToMiddle,  ///< the cord planner's fallback: along the inward normal to the object's middle
};

/// The object's thickness at surface point `p_O` along the inward normal `z_O`: the distance to
/// the first surface beyond it within `reach_m`, 0 when there is none [m]. `bvh`: the mesh's
/// (the same hits in logarithmic time; null: every triangle is tested).
double thickness_m(const Mesh& mesh, const MeshBvh* bvh, const Eigen::Vector3d& p_O,
                   const Eigen::Vector3d& z_O, double reach_m);

/// The sampled planners' attempts: area-weighted random surface points drawn with params.seed,
/// the GCP there along the inward normal at a random roll, approached as `approach` says.
/// Appends force-closure grasps that differ from those in `result` until it holds
/// params.grasps, or `max_attempts` more attempts, params.time_limit_s (`offset_s` + the time
/// since `start`) or `cancel`; counts into result.stats.
void sample_surface_grasps(const Mesh& mesh, const HandModel& hand, HandObjectCollider& collider,
                           const PlanContext& ctx, const PlanParams& params,
                           SampledApproach approach, int max_attempts,
                           std::chrono::steady_clock::time_point start, double offset_s,
                           const CancelToken& cancel, PlanResult& result);

/// sample_surface_grasps() on its own, params.max_attempts attempts, timed: the generic
/// planner (kNone) and the cord planner's fallback (kToMiddle). `context` as for the planners.
PlanResult plan_sampled_grasps(const Mesh& mesh, const HandModel& hand,
                               HandObjectCollider& collider, const PlanParams& params,
                               SampledApproach approach, const CancelToken& cancel,
                               const PlanContext* context);

}  // namespace cordgrasp::internal
