#pragma once
// Validated planning: the planner's force-closure candidates, best first, through physics until
// enough of them hold (docs/algorithm.md §10a).
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "cordgrasp/core/cancel_token.h"
#include "cordgrasp/core/cord_params.h"
#include "cordgrasp/core/grasp.h"
#include "cordgrasp/core/grasp_plan.h"
#include "cordgrasp/core/hand_model.h"
#include "cordgrasp/core/mesh.h"
#include "cordgrasp/sim/grasp_validation.h"
#include "cordgrasp/sim/sim_params.h"

namespace cordgrasp {

/// One line of progress ("candidate 4: held in 3 / 3 trials, accepted (2 / 3)").
using ValidatedPlanProgress = std::function<void(const std::string&)>;

/// What plan_validated_grasps() returns.
struct ValidatedPlan {
  std::vector<Grasp> grasps;  ///< accepted, in order
  /// The planner's counts and times summed over its calls; total_s the whole plan [s],
  /// timed_out = validation.stats.budget_spent, interrupted as below.
  PlanStats stats;
  PlanValidation validation;  ///< params = the rules given, stats, one GraspValidation per grasp
  bool interrupted = false;   ///< stopped by `cancel`
};

/// Plans `plan.grasps` grasps that hold: asks the planner for one force-closure candidate at a
/// time (the cord planner, with `cord`, continues in its region order, exploring again with
/// seed + 1, + 2, + 3 once every region is processed; the generic one is called with the next
/// seed), skips candidates that do not differ from an accepted one (grasps_differ), simulates
/// the rest as planned (early rejection by sim.squeeze_shift_limit_m), then up to
/// `rules.trials` − 1 more times nudged (perturbed_grasp, seed trial_seed + 1000·c + t for
/// candidate c, trial t), `jobs` trials at a time until the verdict is decided, and accepts
/// those held in ≥ min_held trials (with require_held_as_planned, only if the first, as
/// planned, is one of them: else the candidate is dropped after its first trial), until enough
/// are accepted or rules.budget_s is spent (checked before each candidate). `plan` and `cord`
/// are used as given (seeds and soft-finger radius resolved, as plan_document_for does); the
/// planner's own time limit gives way to the budget. Every trial runs with `sim` (its
/// squeeze_shift_limit_m set by the caller) and rules.tests; rules.protocol, physics and
/// physics_file are not read (they made `sim`). Deterministic for given seeds (timings aside)
/// unless the budget stops it. `cancel` is checked before each candidate, in the planner and
/// between trial batches: the candidate in flight is abandoned (not accepted), the result
/// holds the grasps accepted before and `interrupted` is set.
/// @throws std::invalid_argument for bad settings (trials, min_held; the cord planner without
/// `cord`).
ValidatedPlan plan_validated_grasps(const Mesh& mesh, const HandModel& hand, PlannerKind planner,
                                    const PlanParams& plan, const std::optional<CordParams>& cord,
                                    const ValidationParams& rules, const SimParams& sim,
                                    int jobs = 1, const ValidatedPlanProgress& progress = {},
                                    const CancelToken& cancel = {});

}  // namespace cordgrasp
