#pragma once
// Settings documents (physics_settings.h, plan_settings.h): a JSON or YAML mapping read as
// JSON, laid over the full settings, and the full settings written back as YAML.
#include <nlohmann/json.hpp>
#include <string>

namespace cordgrasp {

/// The file `path` as JSON: parsed as YAML when named *.yaml or *.yml (mappings as objects,
/// plain scalars as null, booleans, integers or numbers where they read as such), else as JSON.
/// `what` ("physics settings 'f.yaml'") starts every error.
/// @throws InputError for an unreadable file or a syntax error.
nlohmann::json read_settings_document(const std::string& path, const std::string& what);

/// Overlays `patch` onto `*base`: objects key by key (recursively), every other value, null
/// included (an unset optional), replaces the base's (unlike JSON merge patch, where null
/// deletes).
void overlay_json(const nlohmann::json& patch, nlohmann::json* base);

/// `j` as a YAML document that read_settings_document() reads back to the same JSON.
std::string settings_yaml(const nlohmann::json& j);

}  // namespace cordgrasp
