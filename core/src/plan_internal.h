#pragma once
// core-internal helpers shared by plan_cord_grasps and plan_generic_grasps.
#include <chrono>

#include "cordgrasp/core/grasp_plan.h"
#include "cordgrasp/core/mesh.h"
#include "cordgrasp/core/plan_context.h"

namespace cordgrasp::internal {

/// Seconds since `start` (steady clock).
inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// make_plan_context(), timed into stats.setup_s.
PlanContext make_plan_context(const Mesh& mesh, const HandModel& hand, HandObjectCollider& collider,
                              const PlanParams& params, PlanStats& stats);

/// Runs the finger stage from X_OG_start, then the quality check; counts the outcome in
/// `stats`. Returns true and fills `grasp` when the grasp is force-closure.
bool attempt_grasp(const HandModel& hand, HandObjectCollider& collider, const PlanContext& ctx,
                   const PlanParams& params, const Eigen::Isometry3d& X_OG_start,
                   double approach_travel_m, PlanStats& stats, Grasp& grasp);

}  // namespace cordgrasp::internal
