#include "cordgrasp/jobs/physics_settings.h"

#include <yaml-cpp/yaml.h>

#include <fstream>
#include <stdexcept>

#include "cordgrasp/core/error.h"
#include "cordgrasp/jobs/sim_json.h"
#include "params_json.h"

namespace cordgrasp {
namespace {

bool has_yaml_extension(const std::string& path) {
  for (const char* ext : {".yaml", ".yml"}) {
    const std::string e(ext);
    if (path.size() > e.size() && path.compare(path.size() - e.size(), e.size(), e) == 0)
      return true;
  }
  return false;
}

/// A YAML node as JSON: mappings as objects, sequences as arrays, plain scalars as null,
/// booleans, integers or numbers where they read as such, else (and quoted) as strings.
nlohmann::json yaml_to_json(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Map: {
      nlohmann::json out = nlohmann::json::object();
      for (const auto& item : node) out[item.first.as<std::string>()] = yaml_to_json(item.second);
      return out;
    }
    case YAML::NodeType::Sequence: {
      nlohmann::json out = nlohmann::json::array();
      for (const auto& item : node) out.push_back(yaml_to_json(item));
      return out;
    }
    case YAML::NodeType::Scalar: {
      const std::string& text = node.Scalar();
      if (node.Tag() != "!") {  // not quoted
        if (text == "null" || text == "~") return nullptr;
        bool b = false;
        if (YAML::convert<bool>::decode(node, b)) return b;
        long long i = 0;
        if (YAML::convert<long long>::decode(node, i)) return i;
        double d = 0.0;
        if (YAML::convert<double>::decode(node, d)) return d;
      }
      return text;
    }
    case YAML::NodeType::Null:
    case YAML::NodeType::Undefined:
      return nullptr;
  }
  return nullptr;
}

nlohmann::json read_settings(const std::string& path, const std::string& what) {
  std::ifstream in(path);
  if (!in) throw InputError(what + ": cannot be read");
  if (has_yaml_extension(path)) {
    try {
      return yaml_to_json(YAML::Load(in));
    } catch (const YAML::ParserException& e) {
      throw InputError(what + ": YAML syntax error at line " + std::to_string(e.mark.line + 1) +
                       ": " + e.msg);
    }
  }
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(what + ": not JSON: " + e.what());
  }
}

/// Overlays `patch` onto `*base`: objects key by key (recursively), every other value, null
/// included (an unset optional), replaces the base's (unlike JSON merge patch, where null
/// deletes).
void overlay_json(const nlohmann::json& patch, nlohmann::json* base) {
  if (!patch.is_object() || !base->is_object()) {
    *base = patch;
    return;
  }
  for (const auto& item : patch.items()) overlay_json(item.value(), &(*base)[item.key()]);
}

void write_yaml(const nlohmann::json& j, YAML::Emitter* out) {
  if (j.is_object()) {
    *out << YAML::BeginMap;
    for (const auto& item : j.items()) {
      *out << YAML::Key << item.key() << YAML::Value;
      write_yaml(item.value(), out);
    }
    *out << YAML::EndMap;
  } else if (j.is_null()) {
    *out << YAML::Null;
  } else if (j.is_boolean()) {
    *out << j.get<bool>();
  } else if (j.is_number()) {
    *out << j.dump();  // the shortest text that reads back to the same number
  } else {
    *out << YAML::DoubleQuoted << j.get<std::string>();
  }
}

}  // namespace

void merge_physics_file(const std::string& path, SimParams* params) {
  const std::string what = "physics settings '" + path + "'";
  const nlohmann::json file = read_settings(path, what);
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
  return params;
}

std::string physics_settings_yaml(const SimParams& params) {
  YAML::Emitter out;
  write_yaml(sim_params_to_json(params), &out);
  return std::string(out.c_str()) + "\n";
}

}  // namespace cordgrasp
