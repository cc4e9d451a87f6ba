#pragma once
#include <vector>

#include "cordgrasp/core/grasp_plan.h"
#include "cordgrasp/core/grasp_region.h"
#include "cordgrasp/core/hand_collider.h"
#include "cordgrasp/core/hand_model.h"
#include "cordgrasp/core/mesh.h"

namespace cordgrasp {

/// Target travel D of the approach (spec §7.2): distance from P1 along unit(P_m − P1) to the
/// first surface hit, or ‖P_m − P1‖ when the ray misses [m].
double approach_travel_m(const Mesh& mesh, const GraspRegion& region);

/// Finger stage and force-closure check on grasp regions in ascending χ (spec §7–8), until
/// params.grasps force-closure grasps or the time limit; each region is tried as computed, then
/// rolled 180° if that fails. `regions` may come in any order; `exploration_s` is recorded in
/// the stats and every grasp's times. `collider` must be built for this hand and mesh.
PlanResult plan_cord_grasps_from_regions(const Mesh& mesh, const HandModel& hand,
                                         HandObjectCollider& collider,
                                         const std::vector<GraspRegion>& regions,
                                         const PlanParams& params, double exploration_s = 0.0);

}  // namespace cordgrasp
