#include "cordgrasp/jobs/sim_json.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "cordgrasp/core/atomic_file.h"
#include "cordgrasp/core/error.h"
#include "cordgrasp/core/version.h"
#include "cordgrasp/sim/backend_info.h"
#include "json_util.h"
#include "cordgrasp/jobs/text_format.h"

namespace cordgrasp {

namespace {

constexpr const char* kFormat = "cordgrasp-sim";
constexpr int kFormatVersion = 1;

const char* to_string(WorldFrame frame) {
  return frame == WorldFrame::kApproachDown ? "approach_down" : "object";
}

}  // namespace

nlohmann::json sim_params_to_json(const SimParams& p) {
  const DecompositionParams& d = p.decomposition;
  return {
      {"mu", p.contact.mu},
      {"soft_finger_radius_m", p.contact.soft_finger_radius_m},
      {"link_margin_m", p.link_margin_m},
      {"object_margin_m", p.object_margin_m},
      {"time_step_s", p.time_step_s},
      {"solver_iterations", p.solver_iterations},
      {"erp", p.erp},
      {"contact_stiffness_Npm", p.contact_stiffness_Npm},
      {"contact_damping_Nspm", p.contact_damping_Nspm},
      {"polyhedral_contacts", p.polyhedral_contacts},
      {"solver_residual_threshold", p.solver_residual_threshold},
      {"friction_erp", p.friction_erp},
      {"cfm", p.cfm},
      {"linear_slop_m", p.linear_slop_m},
      {"gear_erp", p.gear_erp},
      {"cone_friction", p.cone_friction},
      {"articulated_warmstarting", p.articulated_warmstarting},
      {"density_kgm3", p.density_kgm3},
      {"mass_kg", p.mass_kg ? nlohmann::json(*p.mass_kg) : nlohmann::json(nullptr)},
      {"object_shape", to_string(p.object_shape)},
      {"convex_volume_ratio", p.convex_volume_ratio},
      {"decomposition",
       {{"concavity", d.concavity},
        {"min_parts", d.min_parts},
        {"max_hull_vertices", d.max_hull_vertices},
        {"compacity_weight", d.compacity_weight},
        {"volume_weight", d.volume_weight},
        {"connect_distance", d.connect_distance},
        {"add_extra_distance_points", d.add_extra_distance_points},
        {"add_face_points", d.add_face_points}}},
      {"close_speed", p.close_speed},
      {"squeeze_rad", p.squeeze_rad},
      {"squeeze_m", p.squeeze_m},
      {"squeeze_direction", to_string(p.squeeze_direction)},
      {"compliant_squeeze", p.compliant_squeeze},
      {"default_effort_Nm", p.default_effort_Nm},
      {"default_effort_N", p.default_effort_N},
      {"effort_scale", p.effort_scale},
      {"servo_gain_per_s", p.servo_gain_per_s},
      {"hold_speed", p.hold_speed},
      {"lock_passive_joints", p.lock_passive_joints},
      {"hand_gravity_compensation", p.hand_gravity_compensation},
      {"base_mass_scale", p.base_mass_scale},
      {"protocol", to_string(p.protocol)},
      {"world_frame", to_string(p.world_frame)},
      {"gravity_mps2", p.gravity_mps2},
      {"settle_time_s", p.settle_time_s},
      {"squeeze_max_time_s", p.squeeze_max_time_s},
      {"squeeze_min_time_s", p.squeeze_min_time_s},
      {"stall_speed", p.stall_speed},
      {"stall_time_s", p.stall_time_s},
      {"lift_height_m", p.lift_height_m},
      {"lift_time_s", p.lift_time_s},
      {"lift_hold_s", p.lift_hold_s},
      {"shake_amplitude_m", p.shake_amplitude_m},
      {"shake_frequency_hz", p.shake_frequency_hz},
      {"shake_time_s", p.shake_time_s},
      {"rock_angle_rad", p.rock_angle_rad},
      {"rock_frequency_hz", p.rock_frequency_hz},
      {"rock_time_s", p.rock_time_s},
      {"gravity6_time_s", p.gravity6_time_s},
      {"reach_start_fraction", p.reach_start_fraction},
      {"reach_start_clearance_m", p.reach_start_clearance_m},
      {"rest_exit_time_s", p.rest_exit_time_s},
      {"rest_drift_m", p.rest_drift_m},
      {"rest_drift_rad", p.rest_drift_rad},
      {"exit_on_failure", p.exit_on_failure},
      {"no_contact_exit_time_s", p.no_contact_exit_time_s},
      {"held_translation_m", p.held_translation_m},
      {"held_rotation_rad", p.held_rotation_rad},
      {"contact_distance_m", p.contact_distance_m},
      {"unstable_speed_mps", p.unstable_speed_mps},
      {"drop_distance_m", p.drop_distance_m},
  };
}

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
                      {"sim_time_s", p.sim_time_s},
                      {"wall_time_s", p.wall_time_s},
                      {"steps", p.steps}});
  }
  const PhaseResult* failed = r.failed_phase();
  return {{"outcome", to_string(r.outcome)},
          {"failed_phase", failed ? nlohmann::json(failed->name) : nlohmann::json(nullptr)},
          {"detail", failed ? failed->detail : std::string()},
          {"preshape_overlap", r.preshape_overlap},
          {"wall_time_s", r.wall_time_s},
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
      g["trials"] = {{"count", static_cast<int>(trials.size())},
                     {"held", trials_held},
                     {"outcomes", names}};
      total_trials += static_cast<int>(trials.size());
      held_trials += trials_held;
    }
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
  params["trials"] = repeated ? static_cast<int>(doc.trial_outcomes.front().size()) : 1;
  params["trial_offset_m"] = doc.trial_perturbation.offset_m;
  params["trial_turn_rad"] = doc.trial_perturbation.turn_rad;
  params["trial_seed"] = doc.trial_seed;
  return {{"format", kFormat},
          {"format_version", kFormatVersion},
          {"cordgrasp_version", version()},
          {"backend", sim_backend_version()},
          {"inputs",
           {{"plan", doc.plan_path},
            {"hand", {{"name", doc.hand_name}, {"path", doc.hand_path}}},
            {"object", {{"path", doc.object_path}, {"name", doc.object_name},
                        {"units", doc.object_units}, {"triangles", doc.object_triangles}}},
            {"plan_seed", doc.plan_seed ? nlohmann::json(*doc.plan_seed)
                                        : nlohmann::json(nullptr)}}},
          {"parameters", params},
          {"object", object},
          {"grasps", grasps},
          {"summary",
           {{"grasps", static_cast<int>(doc.results.size())},
            {"held", held},
            {"outcomes", outcomes},
            {"not_held_by_phase", not_held_by_phase},
            {"preshape_overlaps", failures.preshape_overlaps},
            {"wall_time_s", doc.wall_time_s},
            {"trials", repeated ? nlohmann::json(total_trials) : nlohmann::json(nullptr)},
            {"held_trials", repeated ? nlohmann::json(held_trials) : nlohmann::json(nullptr)}}}};
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
  return j;
}

}  // namespace cordgrasp
