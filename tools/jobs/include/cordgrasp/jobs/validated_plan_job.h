#pragma once
// The validated planning job (`plan --validate`, `run`, `bench`, Python plan_validated): the
// plan document, its physics settings and the algorithm (sim/plan_validated_grasps.h,
// docs/algorithm.md §10a).
#include <string>

#include "cordgrasp/core/cancel_token.h"
#include "cordgrasp/core/hand_model.h"
#include "cordgrasp/core/mesh.h"
#include "cordgrasp/jobs/plan_job.h"
#include "cordgrasp/jobs/plan_json.h"
#include "cordgrasp/sim/grasp_validation.h"
#include "cordgrasp/sim/plan_validated_grasps.h"

namespace cordgrasp {

/// Plans `job.plan.grasps` grasps that hold (plan_validated_grasps) with the parameters of
/// plan_document_for(job, ...) and the physics of physics_settings(): v.protocol, the plan's
/// contact model, v.physics and v.physics_file (decompositions cached in `cache_dir`), with
/// v.squeeze_shift_limit_m. The document holds only accepted grasps, with doc.validation
/// filled; when `cancel` stopped it, doc.interrupted names the signal. Deterministic for given
/// seeds (timings aside) unless the budget stops it.
/// @throws std::invalid_argument for bad settings (trials, min_held); InputError naming the
/// physics settings file (before any simulation).
PlanDocument validated_plan_job(const PlanJobParams& job, const ValidationParams& v,
                                const Mesh& mesh, const std::string& object_path,
                                const HandModel& hand, int jobs = 1,
                                const ValidatedPlanProgress& progress = {},
                                const CancelToken& cancel = {},
                                const std::string& cache_dir = "");

/// "accepted 3 / 3 (12 candidates: 2 similar, 10 simulated, 4 rejected early; first after
/// 2.1 s, 14.3 s in all)".
std::string validation_stats_line(const ValidationStats& s, int wanted);

/// Why `doc` (a plan, validated or not) holds no grasp, for `who` ("plan", "run"): with
/// force-closure candidates that validated planning simulated, that none was accepted (its
/// validation_stats_line, and what to try); otherwise no_grasp_message.
std::string no_accepted_grasp_message(const std::string& who, const PlanDocument& doc,
                                      const Mesh& mesh);

}  // namespace cordgrasp
