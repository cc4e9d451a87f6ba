#include "settings_document.h"

#include <yaml-cpp/yaml.h>

#include <fstream>

#include "cordgrasp/core/error.h"

namespace cordgrasp {
namespace {

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
        if (YAML::convert<long long>::decode(node, i)) {
          if (i >= 0) return static_cast<unsigned long long>(i);  // as JSON reads it
          return i;
        }
        unsigned long long u = 0;  // seeds up to 2^64 - 1
        if (text[0] != '-' && YAML::convert<unsigned long long>::decode(node, u)) return u;
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

}  // namespace

nlohmann::json read_settings_document(const std::string& path, const std::string& what) {
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

void overlay_json(const nlohmann::json& patch, nlohmann::json* base) {
  if (!patch.is_object() || !base->is_object()) {
    *base = patch;
    return;
  }
  for (const auto& item : patch.items()) overlay_json(item.value(), &(*base)[item.key()]);
}

std::string settings_yaml(const nlohmann::json& j) {
  YAML::Emitter out;
  write_yaml(j, &out);
  return std::string(out.c_str()) + "\n";
}

}  // namespace cordgrasp
