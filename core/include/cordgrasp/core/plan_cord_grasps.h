#pragma once
#include <vector>

#include "cordgrasp/core/cancel_token.h"
#include "cordgrasp/core/cord_params.h"
#include "cordgrasp/core/explore_cords.h"
#include "cordgrasp/core/grasp_plan.h"
#include "cordgrasp/core/grasp_region.h"
#include "cordgrasp/core/hand_collider.h"
#include "cordgrasp/core/hand_model.h"
#include "cordgrasp/core/mesh.h"
#include "cordgrasp/core/plan_context.h"

namespace cordgrasp {

/// Target travel D of the approach (docs/algorithm.md §7.2): distance from P1 along unit(P_m − P1)
/// to the first surface hit, or ‖P_m − P1‖ when the ray misses [m].
double approach_travel_m(const Mesh& mesh, const GraspRegion& region);

/// The same travel with the object's vertex mean and its bounding radius about it given, and
/// its BVH (the same hits in logarithmic time; null: every triangle is tested).
double approach_travel_m(const Mesh& mesh, const GraspRegion& region,
                         const Eigen::Vector3d& vertex_mean_O, double radius_m, const MeshBvh* bvh);

/// Finger stage and force-closure check on grasp regions in ascending χ (docs/algorithm.md §7–§8),
/// until params.grasps force-closure grasps or the time limit; each region is tried as computed,
/// then rolled 180° if that fails. `regions` may come in any order; `order`, when given, is the
/// processing order instead (indices into `regions`); a grasp's region_rank is its region's
/// position in the processing order. `exploration_s` is recorded in the stats and every grasp's
/// times. `collider` must be built for this hand and mesh. `cancel` is checked before each
/// region (PlanStats::interrupted). `context`, when given, is make_plan_context() of this mesh,
/// hand and params, made once for many calls (PlanStats::setup_s then counts nothing).
PlanResult plan_cord_grasps_from_regions(const Mesh& mesh, const HandModel& hand,
                                         HandObjectCollider& collider,
                                         const std::vector<GraspRegion>& regions,
                                         const PlanParams& params, double exploration_s = 0.0,
                                         const std::vector<int>* order = nullptr,
                                         const CancelToken& cancel = {},
                                         const PlanContext* context = nullptr);

/// Processing order of the cord planner: regions in ascending χ, except that sets shrunk by
/// SideCordPolicy::kShrink (n below cords_per_side(), docs/algorithm.md §4) come after every full
/// set. Shrunk sets have fewer, less tilted cords, hence a lower χ for reasons unrelated to the
/// object's shape (on the long cylinder they rank oblique corner sets first). Likewise under
/// SideCordPolicy::kFallback the sets are ordered by their number of missed (empty) cords, then
/// by χ: every set whose cords all touch the object first, then the sets that miss fewest (an
/// empty cord costs only A(Q_0), so a small cap at the object's edge that misses most of the
/// scan would otherwise outrank a set that wraps the object). With kDiscardSet and
/// kEmptyWhenMissed this is plain ascending χ.
std::vector<int> cord_region_order(const std::vector<GraspRegion>& regions, double palm_width_m,
                                   const CordParams& cord);

/// The cord planner's fallback on its own (docs/algorithm.md §10): the generic planner's sampled
/// surface points (params.seed, up to params.max_attempts attempts), each approached along the
/// inward normal until the GCP reaches the object's middle (half its thickness there) or the
/// hand collides, not only retreated from the surface: opposed digits then close across the
/// object instead of pinching the near surface. Grasps without a region. `context` as for
/// plan_cord_grasps_from_regions().
PlanResult plan_cord_fallback_grasps(const Mesh& mesh, const HandModel& hand,
                                     HandObjectCollider& collider, const PlanParams& params,
                                     const CancelToken& cancel = {},
                                     const PlanContext* context = nullptr);

/// The cord-driven planner (paper §III–§V): explore_cords() with W_palm = palm_width(hand), then
/// plan_cord_grasps_from_regions() in cord_region_order(); with fewer than params.grasps grasps
/// when the regions or params.max_attempts are spent, up to params.fallback_attempts more
/// attempts as plan_cord_fallback_grasps() makes them (params.seed; grasps without a region,
/// PlanStats::sampled_attempts). The exploration shares
/// params.time_limit_s (its own cap is min(cord.time_limit_s, params.time_limit_s)).
/// `exploration`, when given, receives its stats; `cancel` stops the finger stage early (the
/// exploration runs to its end). `threads`: explore_cords()'s, and above 1 the object's part of
/// the plan context is made beside the exploration (the result does not depend on it).
PlanResult plan_cord_grasps(const Mesh& mesh, const HandModel& hand, HandObjectCollider& collider,
                            const CordParams& cord, const PlanParams& params,
                            ExplorationStats* exploration = nullptr,
                            const CancelToken& cancel = {}, int threads = 1);

}  // namespace cordgrasp
