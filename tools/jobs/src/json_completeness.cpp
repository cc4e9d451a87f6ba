#include "cordgrasp/jobs/json_completeness.h"

#include "cordgrasp/core/error.h"

namespace cordgrasp {

void mark_completeness(nlohmann::json* doc, const std::string& interrupted) {
  (*doc)["complete"] = interrupted.empty();
  if (!interrupted.empty()) (*doc)["interrupted"] = interrupted;
}

std::string read_interrupted(const nlohmann::json& doc, const std::string& source) {
  if (!doc.is_object() || !doc.contains("complete")) return "";  // older files: complete
  if (!doc.at("complete").is_boolean())
    throw InputError(source + ": complete: not true or false");
  if (doc.at("complete").get<bool>()) return "";
  if (!doc.contains("interrupted")) return "unknown";
  if (!doc.at("interrupted").is_string())
    throw InputError(source + ": interrupted: not a string");
  const std::string why = doc.at("interrupted").get<std::string>();
  return why.empty() ? "unknown" : why;
}

}  // namespace cordgrasp
