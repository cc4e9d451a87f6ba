#pragma once
// Command-line options of validated planning (`plan --validate`, `run`), bound to
// ValidationParams and SimParams fields.
#include <CLI/CLI.hpp>
#include <optional>

#include "cordgrasp/jobs/grasp_validation.h"

namespace cordgrasp::cli {

/// Adds --trials, --min-held, --budget, --squeeze-shift-limit, --min-gcp-distance,
/// --min-hand-turn, --trial-offset, --trial-turn and --trial-seed, bound to `v`.
void add_validation_options(CLI::App* cmd, ValidationParams& v);

/// Adds --mass [kg] and --density [kg/m³] (object mass overrides of the physics).
void add_object_mass_options(CLI::App* cmd, std::optional<double>& mass_kg,
                             std::optional<double>& density_kgm3);

/// Adds --squeeze-weight (SimParams::squeeze_weight_factor override).
void add_squeeze_weight_option(CLI::App* cmd, std::optional<double>& squeeze_weight_factor);

}  // namespace cordgrasp::cli
