#include "cordgrasp/jobs/plan_settings.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "cordgrasp/core/error.h"
#include "cordgrasp/sim/validate_grasp.h"
#include "params_json.h"
#include "settings_document.h"

namespace cordgrasp {
namespace {

/// The settings document's layout (plan_settings.h) over the structs' Serialize visitors.
struct SettingsLayout {
  PlanJobParams* job;
  ValidationParams* validation;

  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit(make_nvp("planner", &job->planner));
    job->plan.Serialize(a);
    a->Visit(make_nvp("cord", &job->cord));
    a->Visit(make_nvp("units", &job->units));
    a->Visit(make_nvp("scale", &job->scale));
    a->Visit(make_nvp("validation", validation));
  }
};

struct KeyRange {
  const char* key;
  double lo, hi;
};
constexpr KeyRange kKeyRanges[] = {
    {"grasps", 1, 10000},
    {"time_limit_s", 1e-3, 1e6},
    {"max_attempts", 1, 1e8},
    {"quality.contact.mu", 0, 10},
    {"quality.contact.cone_edges", 3, 64},
    {"quality.contact.soft_finger_radius_m", 0, 0.0499},
    {"diversity.min_gcp_distance_m", 0, 10},
    {"diversity.min_gcp_distance_per_radius", 0, 10},
    {"diversity.min_hand_turn_deg", 0, 180},
    {"cord.sets", 1, 100000},
    {"scale", 1e-6, 1000},
    {"validation.trials", 1, 1000},
    {"validation.min_held", 1, 1000},
    {"validation.min_hold_probability", 0.01, 0.99},
    {"validation.max_draws", 1, 1000},
    {"validation.budget_s", 1e-3, 1e6},
    {"validation.squeeze_shift_limit_m", 0, 10},
    {"validation.perturbation.offset_m", 0, 0.1},
    {"validation.perturbation.turn_rad", 0, 0.5},
    {"validation.physics.mass_kg", 1e-6, 1e4},
    {"validation.physics.density_kgm3", 1, 1e5},
    {"validation.physics.squeeze_weight_factor", 0, 1e4},
};

nlohmann::json settings_json(const PlanJobParams& job, const ValidationParams& validation) {
  PlanJobParams j = job;
  ValidationParams v = validation;
  if (j.soft_finger_radius_m) j.plan.quality.contact.soft_finger_radius_m = *j.soft_finger_radius_m;
  JsonWriteArchive out;
  SettingsLayout{&j, &v}.Serialize(&out);
  return out.json();
}

void check_numbers(const nlohmann::json& j, const std::string& path) {
  for (const auto& item : j.items()) {
    const std::string key = path.empty() ? item.key() : path + "." + item.key();
    if (item.value().is_object()) {
      check_numbers(item.value(), key);
      continue;
    }
    if (!item.value().is_number()) continue;
    const double value = item.value().get<double>();
    if (!std::isfinite(value)) throw std::invalid_argument(key + ": not a finite number");
    for (const KeyRange& r : kKeyRanges)
      if (key == r.key && !(value >= r.lo && value <= r.hi)) {
        std::ostringstream why;
        why << key << ": " << value << " is not in [" << r.lo << ", " << r.hi << "]";
        throw std::invalid_argument(why.str());
      }
  }
}

/// The settings of a plan.json (read_plan_json: upgraded to the current format) in the
/// document's layout.
nlohmann::json plan_file_settings(const std::string& path) {
  const nlohmann::json plan = read_plan_json(path);
  nlohmann::json patch = plan.at("parameters");
  patch.erase("palm_width_m");
  if (patch.contains("cord") && patch["cord"].is_null()) patch.erase("cord");  // generic
  const nlohmann::json& object = plan.at("inputs").at("object");
  for (const char* key : {"units", "scale"})
    if (object.contains(key)) patch[key] = object[key];
  if (plan.contains("validation")) patch["validation"] = plan["validation"].at("parameters");
  return patch;
}

}  // namespace

std::pair<double, double> plan_settings_range(const std::string& key) {
  for (const KeyRange& r : kKeyRanges)
    if (key == r.key) return {r.lo, r.hi};
  throw std::invalid_argument("plan_settings_range: no range for '" + key + "'");
}

void check_plan_settings(const PlanJobParams& job, const ValidationParams& validation) {
  check_numbers(settings_json(job, validation), "");
  if (job.soft_finger_radius_m) {
    const auto [lo, hi] = plan_settings_range("quality.contact.soft_finger_radius_m");
    if (!(*job.soft_finger_radius_m >= lo && *job.soft_finger_radius_m <= hi))
      throw std::invalid_argument("quality.contact.soft_finger_radius_m: not in [0, 0.0499]");
  }
  if (validation.min_held > validation.trials)
    throw std::invalid_argument("validation.min_held: " + std::to_string(validation.min_held) +
                                " is more than validation.trials (" +
                                std::to_string(validation.trials) + ")");
  try {
    check_uncertainty_params(validation.uncertainty);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("validation.uncertainty.") + e.what());
  }
  try {
    (void)sim_tests_from_string(validation.tests);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("validation.tests: ") + e.what());
  }
}

void merge_plan_settings_file(const std::string& path, PlanJobParams* job,
                              ValidationParams* validation) {
  const std::string what = "planner settings '" + path + "'";
  const nlohmann::json file = read_settings_document(path, what);
  if (!file.is_object()) throw InputError(what + ": expected a mapping of planner settings");
  const bool is_plan = file.value("format", std::string()) == "cordgrasp-plan";
  const nlohmann::json patch = is_plan ? plan_file_settings(path) : file;
  nlohmann::json merged = settings_json(*job, *validation);
  overlay_json(patch, &merged);
  PlanJobParams j = *job;
  ValidationParams v = *validation;
  SettingsLayout layout{&j, &v};
  params_from_json(merged, what, "", &layout);
  const nlohmann::json* contact = &patch;
  for (const char* key : {"quality", "contact"})
    if (contact && contact->is_object() && contact->contains(key))
      contact = &contact->at(key);
    else
      contact = nullptr;
  if (contact && contact->is_object() && contact->contains("soft_finger_radius_m"))
    j.soft_finger_radius_m = j.plan.quality.contact.soft_finger_radius_m;
  try {
    check_plan_settings(j, v);
  } catch (const std::invalid_argument& e) {
    throw InputError(what + ": " + e.what());
  }
  *job = j;
  *validation = v;
}

std::string plan_settings_yaml(const PlanJobParams& job, const ValidationParams& validation) {
  return settings_yaml(settings_json(job, validation));
}

}  // namespace cordgrasp
