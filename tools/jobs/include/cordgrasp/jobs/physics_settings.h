#pragma once
// Physics settings documents (docs/physics.md §5a): a partial SimParams in JSON or YAML, merged
// over a protocol preset, so that an experiment is a file and any run can be repeated.
#include <optional>
#include <string>

#include "cordgrasp/core/contact_model.h"
#include "cordgrasp/sim/sim_params.h"

namespace cordgrasp {

/// What decides the physics settings of a plan's simulations (physics_settings), in the
/// order it applies.
struct PhysicsChoice {
  Protocol protocol = SimParams{}.protocol;  ///< the preset
  std::optional<double> mu;  ///< friction over the plan's μ (CLI --mu); unset: the plan's
  SimOverrides overrides;    ///< mass, density, squeeze weight (CLI --mass, ...), completed...
  SimOverrides recorded;     ///< ...from those a validated plan was accepted with
  std::string cache_dir;     ///< decomposition cache folder (CLI --cache-dir); empty: none
  std::string file;          ///< settings file merged last (merge_physics_file); empty: none
};

/// The SimParams a plan's grasps are simulated with: `choice.protocol`'s preset, the plan's
/// contact model `plan_contact` (μ: choice.mu if set), the mass, density and squeeze weight of
/// choice.overrides completed from choice.recorded (sim_overrides_or), the cache folder, then
/// choice.file, which has the last word. Every command, the benchmarks and the Python module
/// build a plan's physics settings here.
/// @throws InputError naming the settings file (merge_physics_file).
SimParams physics_settings(const ContactModel& plan_contact, const PhysicsChoice& choice);

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
