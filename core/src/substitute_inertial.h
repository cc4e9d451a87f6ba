#pragma once
// Internal to hand loading: replacement of missing, placeholder or impossible URDF inertials
// (rules in docs/hand-description.md, URDF handling).
#include <string>
#include <vector>

#include "cordgrasp/core/hand_model.h"

namespace cordgrasp::hand_load {

/// Replaces link.inertial when it is missing (`declared` false) or implausible for the link's
/// geometry bounds; sets Inertial::substituted and returns true when it did.
bool substitute_inertial_if_needed(Link& link, bool declared);

/// Prints one warning per URDF path and process naming the links whose inertial was replaced.
void warn_substituted_once(const std::string& urdf_path, const std::vector<std::string>& names);

}  // namespace cordgrasp::hand_load
