#include "cordgrasp/jobs/sim_json.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "cordgrasp/core/atomic_file.h"
#include "cordgrasp/core/error.h"
#include "cordgrasp/core/version.h"
#include "cordgrasp/sim/backend_info.h"
#include "cordgrasp/jobs/json_completeness.h"
#include "json_util.h"
#include "params_json.h"
#include "cordgrasp/jobs/text_format.h"

namespace cordgrasp {

namespace {

constexpr const char* kFormat = "cordgrasp-sim";
constexpr int kFormatVersion = 2;
}  // namespace

nlohmann::json sim_params_to_json(const SimParams& p) { return params_to_json(p); }

namespace {

/// A grasp's hold_probability block: the estimate, each draw and the sensitivity.
nlohmann::json hold_probability_to_json(const HoldProbability& h) {
  nlohmann::json draws = nlohmann::json::array();
  for (const UncertainDrawResult& d : h.draws) {
    nlohmann::json scores = nlohmann::json::object();
    for (int i = 0; i < kUncertaintyFactors; ++i)
      scores[to_string(static_cast<UncertaintyFactor>(i))] = d.draw.scores[static_cast<size_t>(i)];
    draws.push_back({{"trial", d.trial},
                     {"outcome", to_string(d.outcome)},
                     {"failed_phase", d.failed_phase.empty() ? nlohmann::json(nullptr)
                                                             : nlohmann::json(d.failed_phase)},
                     {"hand_offset_G_m", to_json(d.draw.hand_offset_G_m)},
                     {"hand_turn_G_rad", to_json(d.draw.hand_turn_G_rad)},
                     {"mu_factor", d.draw.mu_factor},
                     {"mass_factor", d.draw.mass_factor},
                     {"com_offset_O_m", to_json(d.draw.com_offset_O_m)},
                     {"squeeze_factor", d.draw.squeeze_factor},
                     {"scores", scores},
                     {"wall_time_s", d.wall_time_s},
                     {"cpu_s", d.cpu_s}});
  }
  nlohmann::json factors = nlohmann::json::array();
  for (const FactorSensitivity& f : h.sensitivity.factors)
    factors.push_back({{"factor", to_string(f.factor)},
                       {"mean_score_failed", f.mean_failed},
                       {"mean_score_held", f.mean_held},
                       {"effect", f.effect}});
  return {{"p", h.interval.p},
          {"low", h.interval.low},
          {"high", h.interval.high},
          {"draws", static_cast<int>(h.draws.size())},
          {"held", h.held},
          {"threshold", h.threshold},
          {"decided", h.verdict != HoldVerdict::kUndecided},
          {"verdict", to_string(h.verdict)},
          {"sensitivity",
           {{"factors", factors},
            {"most_associated", h.sensitivity.most_associated
                                    ? nlohmann::json(to_string(*h.sensitivity.most_associated))
                                    : nlohmann::json(nullptr)}}},
          {"wall_time_s", h.wall_time_s},
          {"cpu_s", h.cpu_s},
          {"simulations", h.simulations},
          {"draw_results", draws}};
}

}  // namespace

nlohmann::json sim_result_to_json(const SimResult& r, const HandModel& hand) {
  nlohmann::json phases = nlohmann::json::array();
  for (const PhaseResult& p : r.phases) {
    nlohmann::json efforts = nlohmann::json::object();
    for (size_t j = 0; j < p.joint_efforts.size() && j < hand.joints.size(); ++j)
      if (hand.joints[j].is_moving()) efforts[hand.joints[j].name] = p.joint_efforts[j];
    phases.push_back({{"name", p.name},
                      {"outcome", to_string(p.outcome)},
                      {"detail", p.detail},
                      {"translation_m", p.translation_m},
                      {"rotation_rad", p.rotation_rad},
                      {"max_translation_m", p.max_translation_m},
                      {"in_contact", p.in_contact},
                      {"contact_count", p.contact_count},
                      {"max_contact_count", p.max_contact_count},
                      {"max_penetration_m", p.max_penetration_m},
                      {"joint_efforts", efforts},
                      {"squeeze_effort_ratio", p.squeeze_effort_ratio},
                      {"sim_time_s", p.sim_time_s},
                      {"wall_time_s", p.wall_time_s},
                      {"steps", p.steps}});
  }
  const PhaseResult* failed = r.failed_phase();
  nlohmann::json offsets = nlohmann::json::array();
  for (const double d : r.planned_contact_offsets_m)
    offsets.push_back(std::isfinite(d) ? nlohmann::json(d) : nlohmann::json(nullptr));
  return {{"outcome", to_string(r.outcome)},
          {"failed_phase", failed ? nlohmann::json(failed->name) : nlohmann::json(nullptr)},
          {"detail", failed ? failed->detail : std::string()},
          {"preshape_overlap", r.preshape_overlap},
          {"wall_time_s", r.wall_time_s},
          {"planned_contact_offsets_m", offsets},
          {"weight_margin", r.weight_margin ? nlohmann::json(*r.weight_margin) : nlohmann::json()},
          {"phases", phases}};
}

nlohmann::json sim_to_json(const SimDocument& doc, const HandModel& hand) {
  nlohmann::json grasps = nlohmann::json::array();
  int held = 0;
  std::map<std::string, int> outcomes = {{"held", 0}, {"slipped", 0}, {"dropped", 0},
                                         {"unstable", 0}};
  int total_trials = 0;
  int held_trials = 0;
  for (size_t k = 0; k < doc.results.size(); ++k) {
    nlohmann::json g = sim_result_to_json(doc.results[k], hand);
    g["index"] = k < doc.grasp_indices.size() ? doc.grasp_indices[k] : static_cast<int>(k);
    if (k < doc.grasps.size()) {
      g["epsilon"] = doc.grasps[k].epsilon;
      g["force_closure"] = doc.grasps[k].force_closure;
    }
    if (k < doc.trial_outcomes.size()) {
      const std::vector<Outcome>& trials = doc.trial_outcomes[k];
      nlohmann::json names = nlohmann::json::array();
      for (Outcome o : trials) names.push_back(to_string(o));
      const int trials_held = count_held(trials);
      nlohmann::json shifts = nlohmann::json::array(), turns = nlohmann::json::array();
      if (k < doc.trial_close_motion.size())
        for (const auto& [shift_m, turn_rad] : doc.trial_close_motion[k]) {
          shifts.push_back(std::isfinite(shift_m) ? nlohmann::json(shift_m) : nlohmann::json());
          turns.push_back(std::isfinite(turn_rad) ? nlohmann::json(turn_rad) : nlohmann::json());
        }
      g["trials"] = {{"count", static_cast<int>(trials.size())},
                     {"held", trials_held},
                     {"outcomes", names},
                     {"close_shift_m", shifts},
                     {"close_turn_rad", turns}};
      total_trials += static_cast<int>(trials.size());
      held_trials += trials_held;
    }
    if (k < doc.hold_probabilities.size())
      g["hold_probability"] = hold_probability_to_json(doc.hold_probabilities[k]);
    grasps.push_back(g);
    held += doc.results[k].held();
    ++outcomes[to_string(doc.results[k].outcome)];
  }
  nlohmann::json object = nlohmann::json(nullptr);
  if (!doc.results.empty()) {
    const SimObjectInfo& o = doc.results.front().object;
    object = {{"shape", to_string(o.shape)},
              {"parts", o.parts},
              {"mass_kg", o.mass_kg},
              {"volume_m3", o.volume_m3},
              {"closed", o.closed},
              {"com_m", to_json(o.com_O)},
              {"principal_inertia_kgm2", to_json(o.principal_inertia_kgm2)},
              {"decomposition_s", o.decomposition_s}};
  }
  const FailureCounts failures = count_failures(doc.results);
  nlohmann::json not_held_by_phase = nlohmann::json::object();
  for (const auto& [name, count] : failures.by_phase) not_held_by_phase[name] = count;
  nlohmann::json params = sim_params_to_json(doc.params);
  params["tests"] = to_string(doc.tests);
  const bool repeated = !doc.trial_outcomes.empty();
  params["trials"] =
      repeated ? static_cast<int>(doc.trial_outcomes.front().size()) : std::max(1, doc.trials);
  params["trial_offset_m"] = doc.trial_perturbation.offset_m;
  params["trial_turn_rad"] = doc.trial_perturbation.turn_rad;
  params["trial_seed"] = doc.trial_seed;
  const bool uncertain = !doc.hold_probabilities.empty();
  params["uncertainty"] = uncertain ? params_to_json(doc.uncertainty) : nlohmann::json(nullptr);
  params["hold_probability"] = uncertain ? params_to_json(doc.hold_test) : nlohmann::json(nullptr);
  nlohmann::json out = {
      {"format", kFormat},
      {"format_version", kFormatVersion},
      {"cordgrasp_version", version()},
      {"backend", sim_backend_version()},
      {"inputs",
       {{"plan", doc.plan_path},
        {"hand", {{"name", doc.hand_name}, {"path", doc.hand_path}}},
        {"object",
         {{"path", doc.object_path},
          {"name", doc.object_name},
          {"units", doc.object_units},
          {"scale", doc.object_scale},
          {"triangles", doc.object_triangles}}},
        {"plan_seed", doc.plan_seed ? nlohmann::json(*doc.plan_seed) : nlohmann::json(nullptr)}}},
      {"parameters", params},
      {"object", object},
      {"grasps", grasps},
      {"summary",
       {{"grasps", static_cast<int>(doc.results.size())},
        {"held", held},
        {"outcomes", outcomes},
        {"not_held_by_phase", not_held_by_phase},
        {"preshape_overlaps", failures.preshape_overlaps},
        {"not_pressing_after_close", failures.not_pressing},
        {"wall_time_s", doc.wall_time_s},
        {"trials", repeated ? nlohmann::json(total_trials) : nlohmann::json(nullptr)},
        {"held_trials", repeated ? nlohmann::json(held_trials) : nlohmann::json(nullptr)}}}};
  mark_completeness(&out, doc.interrupted);
  return out;
}

void write_sim_file(const std::string& path, const SimDocument& doc, const HandModel& hand) {
  write_file_atomically(path, sim_to_json(doc, hand).dump(2) + "\n");
}

nlohmann::json read_sim_json(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError("read_sim: '" + path + "': cannot open file");
  nlohmann::json j;
  try {
    in >> j;
  } catch (const nlohmann::json::exception& e) {
    throw InputError("read_sim: '" + path + "': not valid JSON (" + e.what() + ")");
  }
  if (!j.is_object() || j.value("format", std::string()) != kFormat)
    throw InputError("read_sim: '" + path + "': not a cordgrasp sim file (format != " +
                     kFormat + ")");
  if (j.value("format_version", 0) != kFormatVersion)
    throw InputError("read_sim: '" + path + "': unsupported format_version " +
                     j.value("format_version", nlohmann::json(nullptr)).dump());
  (void)read_interrupted(j, "read_sim: '" + path + "'");  // a wrong type fails here
  return j;
}

}  // namespace cordgrasp
