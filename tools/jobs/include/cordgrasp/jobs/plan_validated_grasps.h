#pragma once
// Validated planning: the planner's force-closure candidates, best first, through physics until
// enough of them hold (docs/algorithm.md §13).
#include <functional>
#include <string>

#include "cordgrasp/core/hand_model.h"
#include "cordgrasp/core/mesh.h"
#include "cordgrasp/jobs/grasp_validation.h"
#include "cordgrasp/jobs/plan_job.h"
#include "cordgrasp/jobs/plan_json.h"
#include "cordgrasp/sim/sim_params.h"

namespace cordgrasp {

/// One line of progress ("candidate 4: held in 3 / 3 trials, accepted (2 / 3)").
using ValidatedPlanProgress = std::function<void(const std::string&)>;

/// Plans `job.plan.grasps` grasps that hold: asks the planner for one force-closure candidate at
/// a time (the cord planner continues in its region order, exploring again with seed + 1, + 2,
/// + 3 once every region is processed; the generic one is called with the next seed),
/// skips candidates that do not differ from an accepted one (grasps_differ), simulates the
/// rest as planned (early rejection by the squeeze shift), then up to `trials` − 1 more times
/// nudged (perturbed_grasp, seed trial_seed + 1000·c + t for candidate c, trial t), `jobs`
/// trials at a time until the verdict is decided, and accepts those held in ≥ min_held trials
/// (with require_held_as_planned, only if the first, as planned, is one of them: else the
/// candidate is dropped after its first trial),
/// until enough are accepted or budget_s is spent (checked before each candidate).
/// The physics: physics_settings() of v.protocol, the plan's contact model, v.physics and
/// v.physics_file (decompositions cached in `cache_dir`). The document holds only accepted
/// grasps, with doc.validation filled. Deterministic for given seeds (timings aside) unless
/// the budget stops it. `cancel` is checked before each candidate, in the planner and
/// between trial batches: the candidate in flight is abandoned (not accepted), the document
/// holds the grasps accepted before and doc.interrupted names the signal.
/// @throws std::invalid_argument for bad settings (trials, min_held).
PlanDocument plan_validated_grasps(const PlanJobParams& job, const ValidationParams& v,
                                   const Mesh& mesh, const std::string& object_path,
                                   const HandModel& hand, int jobs = 1,
                                   const ValidatedPlanProgress& progress = {},
                                   const CancelToken& cancel = {},
                                   const std::string& cache_dir = "");

/// "accepted 3 / 3 (12 candidates: 2 similar, 10 simulated, 4 rejected early; first after
/// 2.1 s, 14.3 s in all)".
std::string validation_stats_line(const ValidationStats& s, int wanted);

}  // namespace cordgrasp
