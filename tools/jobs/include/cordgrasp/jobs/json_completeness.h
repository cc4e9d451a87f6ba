#pragma once
// The top-level "complete" / "interrupted" keys of plan.json, sim.json and bench.json: a job
// stopped early (SIGINT, CancelToken) writes what it finished with "complete": false and the
// signal's name; a job that ran to its end writes "complete": true.
#include <nlohmann/json.hpp>
#include <string>

namespace cordgrasp {

/// Sets doc["complete"] = interrupted.empty() and, when interrupted is not empty,
/// doc["interrupted"] = interrupted ("SIGINT").
void mark_completeness(nlohmann::json* doc, const std::string& interrupted);

/// What stopped the job that wrote `doc` early ("SIGINT"), or "" when it ran to its end (also
/// for files written before these keys existed). @throws InputError naming `source` when
/// "complete" is not a boolean or "interrupted" not a string.
std::string read_interrupted(const nlohmann::json& doc, const std::string& source);

}  // namespace cordgrasp
