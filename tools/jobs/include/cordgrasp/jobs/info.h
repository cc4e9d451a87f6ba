#pragma once
#include <nlohmann/json.hpp>
#include <string>

#include "cordgrasp/core/hand_description.h"

namespace cordgrasp {

/// `info --object`: loads the mesh and summarizes it (sizes in m). @throws InputError.
nlohmann::json object_info_json(const std::string& path, const std::string& units,
                                double scale = 1.0);

/// Human-readable form of object_info_json() on stdout.
void print_object_info(const nlohmann::json& info);

/// `info --hand`: loads the hand (description path or shipped name) and summarizes it: links,
/// joints with limits, GCP, preshape, actors, DOF, mass [kg], palm width [m]. @throws InputError.
nlohmann::json hand_info_json(const std::string& name_or_path,
                              const HandLoadOptions& options = {});

/// Human-readable form of hand_info_json() on stdout.
void print_hand_info(const nlohmann::json& info);

}  // namespace cordgrasp
