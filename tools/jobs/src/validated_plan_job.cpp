#include "cordgrasp/jobs/validated_plan_job.h"

#include <utility>

#include "cordgrasp/jobs/physics_settings.h"
#include "cordgrasp/jobs/text_format.h"

namespace cordgrasp {

PlanDocument validated_plan_job(const PlanJobParams& job, const ValidationParams& v,
                                const Mesh& mesh, const std::string& object_path,
                                const HandModel& hand, int jobs,
                                const ValidatedPlanProgress& progress,
                                const CancelToken& cancel, const std::string& cache_dir) {
  PlanDocument doc = plan_document_for(job, mesh, object_path, hand);
  PhysicsChoice physics;
  physics.protocol = v.protocol;
  physics.overrides = v.physics;
  physics.cache_dir = cache_dir;
  physics.file = v.physics_file;
  SimParams sim = physics_settings(plan_contact_model(doc), physics);
  sim.squeeze_shift_limit_m = v.squeeze_shift_limit_m;
  ValidatedPlan result = plan_validated_grasps(mesh, hand, doc.planner, doc.params, doc.cord, v,
                                               sim, jobs, progress, cancel);
  doc.grasps = std::move(result.grasps);
  doc.stats = result.stats;
  doc.validation = std::move(result.validation);
  if (result.interrupted) doc.interrupted = cancel.reason();
  return doc;
}

std::string validation_stats_line(const ValidationStats& s, int wanted) {
  std::string line = "accepted " + std::to_string(s.accepted) + " / " + std::to_string(wanted) +
                     " (" + std::to_string(s.force_closure) + " force-closure candidates of " +
                     std::to_string(s.attempts) + " attempts: " + std::to_string(s.similar) +
                     " near copies, " + std::to_string(s.simulated) + " simulated, " +
                     std::to_string(s.rejected_early) + " rejected early, " +
                     std::to_string(s.trials_run) + " trials; ";
  if (s.first_accepted_cpu_s)
    line += "first accepted after " + fixed(*s.first_accepted_cpu_s, 1) + " s CPU, ";
  line += fixed(s.cpu_s, 1) + " s CPU in all" + (s.budget_spent ? ", budget spent)" : ")");
  return line;
}

std::string no_accepted_grasp_message(const std::string& who, const PlanDocument& doc,
                                      const Mesh& mesh) {
  if (!doc.validation || doc.validation->stats.force_closure == 0)
    return no_grasp_message(who, doc, mesh);
  const ValidationStats& s = doc.validation->stats;
  return who + ": no grasp of " + doc.object_name + " with " + doc.hand_name +
         " accepted in physics (" + validation_stats_line(s, doc.params.grasps) + "); try " +
         (s.budget_spent ? "a larger validation.budget_s (--settings), " : "") +
         "another --seed or --planner" +
         (is_none(doc.validation->params.uncertainty) ? ""
                                                       : " or a lower --min-hold-probability");
}

}  // namespace cordgrasp
