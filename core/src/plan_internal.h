#pragma once
// core-internal helpers shared by plan_cord_grasps and plan_generic_grasps.
#include <chrono>

#include "cordgrasp/core/grasp_plan.h"
#include "cordgrasp/core/mesh.h"

namespace cordgrasp::internal {

/// Seconds since `start` (steady clock).
inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Per-plan constants: hand setup, wrench-space object, principal axis.
struct PlanContext {
  HandSetup setup;
  WrenchSpaceObject wrench_object;
  Eigen::Vector3d principal_axis_O = Eigen::Vector3d::UnitZ();
  /// Centre of mass at uniform density (closed volume, else convex hull) and bounding radius r.
  Eigen::Vector3d com_O = Eigen::Vector3d::Zero();
  double radius_m = 0.0;
};

/// Builds the PlanContext (timed into stats.setup_s).
PlanContext make_plan_context(const Mesh& mesh, const HandModel& hand, HandObjectCollider& collider,
                              const PlanParams& params, PlanStats& stats);

/// Runs the finger stage from X_OG_start, then the quality check; counts the outcome in
/// `stats`. Returns true and fills `grasp` when the grasp is force-closure.
bool attempt_grasp(const HandModel& hand, HandObjectCollider& collider, const PlanContext& ctx,
                   const PlanParams& params, const Eigen::Isometry3d& X_OG_start,
                   double approach_travel_m, PlanStats& stats, Grasp& grasp);

}  // namespace cordgrasp::internal
