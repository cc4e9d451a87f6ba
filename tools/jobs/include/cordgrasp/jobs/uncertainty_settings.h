#pragma once
// The uncertainty model of `validate --uncertainty` (docs/physics.md §3b): a name or a small
// settings document of UncertaintyParams fields, read like the physics settings.
#include <string>

#include "cordgrasp/sim/grasp_uncertainty.h"

namespace cordgrasp {

/// "none" (uncertainty_none()), "realistic" (UncertaintyParams' defaults), or the path of a
/// JSON (or, named *.yaml / *.yml, YAML) mapping of UncertaintyParams fields laid over the
/// realistic ones, or of a sim.json whose parameters.uncertainty block it reads.
/// @throws InputError naming the file and the field for an unreadable file, a syntax error,
/// an unknown key, a value of the wrong type or out of range.
UncertaintyParams uncertainty_settings(const std::string& choice);

/// `params` as the YAML document uncertainty_settings reads back (every field).
std::string uncertainty_settings_yaml(const UncertaintyParams& params);

}  // namespace cordgrasp
