#pragma once
// Physics settings documents (docs/physics.md §5a): a partial SimParams in JSON or YAML, merged
// over a protocol preset, so that an experiment is a file and any run can be repeated.
#include <string>

#include "cordgrasp/sim/sim_params.h"

namespace cordgrasp {

/// Merges the physics settings file `path` into `*params`: a JSON (or, named *.yaml / *.yml,
/// YAML) mapping with any subset of SimParams' fields (nested ones partially too; null unsets
/// an optional), or a sim.json whose "parameters" block holds them (its keys that are no
/// SimParams field, such as tests and trials, are skipped). The result is checked
/// (check_sim_params).
/// @throws InputError naming the file and the key for an unreadable file, a syntax error, an
/// unknown key, a value of the wrong type or out of range.
void merge_physics_file(const std::string& path, SimParams* params);

/// The settings as the YAML document that merge_physics_file reads back (every field).
std::string physics_settings_yaml(const SimParams& params);

}  // namespace cordgrasp
