#include "cordgrasp/jobs/physics_settings.h"

#include <filesystem>
#include <stdexcept>

#include "cordgrasp/core/error.h"
#include "cordgrasp/jobs/sim_json.h"
#include "params_json.h"
#include "settings_document.h"

namespace cordgrasp {

void merge_physics_file(const std::string& path, SimParams* params) {
  const std::string what = "physics settings '" + path + "'";
  const nlohmann::json file = read_settings_document(path, what);
  if (!file.is_object()) throw InputError(what + ": expected a mapping of SimParams fields");
  nlohmann::json patch = file;
  if (file.contains("format") && file.contains("parameters")) {
    // A sim.json: its parameters block, less the keys that are no SimParams field.
    const nlohmann::json fields = sim_params_to_json(*params);
    patch = nlohmann::json::object();
    for (const auto& item : file.at("parameters").items())
      if (fields.contains(item.key())) patch[item.key()] = item.value();
  }
  nlohmann::json merged = sim_params_to_json(*params);
  overlay_json(patch, &merged);
  SimParams out;
  params_from_json(merged, what, "", &out);
  try {
    check_sim_params(out);
  } catch (const std::invalid_argument& e) {
    throw InputError(what + ": " + e.what());
  }
  *params = out;
}

SimParams physics_settings(const ContactModel& plan_contact, const PhysicsChoice& choice) {
  SimParams params = sim_params_for(choice.protocol);
  params.contact = plan_contact;  // one friction model for planner and physics
  if (choice.mu) params.contact.mu = *choice.mu;
  apply_sim_overrides(sim_overrides_or(choice.overrides, choice.recorded), &params);
  params.decomposition_cache_dir = choice.cache_dir;
  if (!choice.file.empty()) merge_physics_file(choice.file, &params);
  if (!params.decomposition_cache_dir.empty() &&
      !std::filesystem::is_directory(params.decomposition_cache_dir))
    throw InputError("physics settings: decomposition_cache_dir '" +
                     params.decomposition_cache_dir + "' is not a directory");
  return params;
}

std::string physics_settings_yaml(const SimParams& params) {
  return settings_yaml(sim_params_to_json(params));
}

}  // namespace cordgrasp
