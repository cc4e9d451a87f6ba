#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace cordgrasp::cli {

/// `info --object`: loads the mesh and summarizes it (sizes in m). @throws InputError.
nlohmann::json object_info_json(const std::string& path, const std::string& units);

/// Human-readable form of object_info_json() on stdout.
void print_object_info(const nlohmann::json& info);

}  // namespace cordgrasp::cli
