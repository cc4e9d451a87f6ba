#pragma once
// Command-line options of validated planning (`plan --validate`, `run`), bound to
// ValidationParams and SimParams fields.
#include <CLI/CLI.hpp>
#include <optional>

#include "cordgrasp/sim/grasp_validation.h"

namespace cordgrasp::cli {

/// Help of every --protocol option: the presets and what sets them apart.
extern const char* const kProtocolHelp;

/// Help of every --physics option: a settings file over the protocol.
extern const char* const kPhysicsHelp;

/// Adds --uncertainty (none, realistic or a file: uncertainty_settings) and
/// --min-hold-probability of the P(held) test of validated planning, bound to `v`; `use`
/// (when given) replaces the first sentence of --uncertainty's help.
void add_uncertainty_options(CLI::App* cmd, ValidationParams& v, const char* use = nullptr);

/// Adds --validate [PROTOCOL]: sets *validate, and *protocol when a protocol is named.
void add_validate_option(CLI::App* cmd, bool* validate, Protocol* protocol);

/// Adds --mass [kg], --density [kg/m³] and --squeeze-weight, bound to `o`; `recorded_note`
/// ("the plan's, else ") prefixes the defaults in the help.
void add_sim_override_options(CLI::App* cmd, SimOverrides& o,
                              const std::string& recorded_note = "");

}  // namespace cordgrasp::cli
