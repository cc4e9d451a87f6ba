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

namespace {

/// "2 rejected early; lost as planned in close 1, lift 5, shake 1; 2 in later trials": where the
/// simulated candidates that were not accepted failed.
std::string losses_text(const ValidationStats& s) {
  std::string text = std::to_string(s.rejected_early) + " rejected early";
  std::string phases;
  const auto add = [&](const char* phase, int n, bool always) {
    if (n == 0 && !always) return;
    phases += (phases.empty() ? "" : ", ") + std::string(phase) + " " + std::to_string(n);
  };
  add("close", s.lost_in_close, true);
  add("lift", s.lost_in_lift, true);
  add("shake", s.lost_in_shake, true);
  add("gravity6", s.lost_in_gravity6, false);
  text += "; lost as planned in " + phases;
  std::string why;
  if (s.lost_not_pressing > 0)
    why =
        std::to_string(s.lost_not_pressing) + " after the close with no finger pressing the object";
  if (s.lost_below_weight_margin > 0)
    why += (why.empty() ? "" : ", ") + std::to_string(s.lost_below_weight_margin) +
           " with contacts too weak for the weight";
  if (!why.empty()) text += " (" + why + ")";
  text += "; " + std::to_string(s.lost_in_later_trials) + " in later trials";
  return text;
}

}  // namespace

std::string validation_stats_line(const ValidationStats& s, int wanted) {
  std::string line = "accepted " + std::to_string(s.accepted) + " / " + std::to_string(wanted) +
                     " (" + std::to_string(s.force_closure) + " force-closure candidates of " +
                     std::to_string(s.attempts) + " attempts: " + std::to_string(s.similar) +
                     " near copies, " + std::to_string(s.simulated) + " simulated (" +
                     losses_text(s) + "), " + std::to_string(s.trials_run) + " trials; ";
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
  // Most candidates dropped by gravity: the grip, not the planner, is short: the planned
  // contacts cannot carry the weight within the effort limits, or no finger pressed, or the
  // object slipped or turned in a grip strong enough at rest.
  const int after_close = s.lost_in_lift + s.lost_in_shake + s.lost_in_gravity6;
  std::string grip;
  if (2 * (s.lost_in_lift + s.lost_in_shake) > s.simulated) {
    if (2 * s.lost_below_weight_margin > after_close)
      grip = "; most candidates lost the object (" + fixed(s.object_mass_kg, 3) +
             " kg) in lift or shake with planned contacts that cannot carry its weight within "
             "the hand's joint effort limits (weight margin below 1, "
             "finger-stage-and-quality.md): the hand is too weak for it there (mass_kg in the "
             "physics settings sets the mass)";
    else if (2 * s.lost_not_pressing > after_close)
      grip =
          "; most candidates lost the object in lift or shake with no finger pressing it "
          "at the end of the close: the fingers ended on the planned contacts without load, "
          "or short of them (the squeeze goes squeeze_travel_m past them, physics.md §3a)";
    else
      grip = "; most candidates lost the object (" + fixed(s.object_mass_kg, 3) +
             " kg) in lift or shake although their contacts could carry its weight: it slipped "
             "or turned in a grip strong enough at rest";
  }
  return who + ": no grasp of " + doc.object_name + " with " + doc.hand_name +
         " accepted in physics (" + validation_stats_line(s, doc.params.grasps) + ")" + grip +
         "; try " + (s.budget_spent ? "a larger validation.budget_s (--settings), " : "") +
         "another --seed or --planner" +
         (is_none(doc.validation->params.uncertainty) ? "" : " or a lower --min-hold-probability");
}

}  // namespace cordgrasp
