#pragma once
// The cordgrasp subcommands: each cmd_<name>.cpp defines one add_<name>_command, and main.cpp
// adds them, in the order --help lists them.
#include <CLI/CLI.hpp>

#include "cordgrasp/core/cancel_token.h"

namespace cordgrasp::cli {

/// For the commands that stop cleanly (run, plan, validate, bench; main.cpp): the first SIGINT
/// or SIGTERM sets the flag interrupt_token() views, the job writes what finished marked
/// incomplete, the command throws Interrupted and main exits with kExitInterrupted (130); the
/// handler then gives both signals back their default action, so a second one ends the
/// process at once. A signal ignored when the process started stays ignored.
void install_interrupt_handlers();
CancelToken interrupt_token();

void add_run_command(CLI::App& app);             ///< cmd_run.cpp
void add_info_command(CLI::App& app);            ///< cmd_info.cpp
void add_explore_command(CLI::App& app);         ///< cmd_explore.cpp
void add_plan_command(CLI::App& app);            ///< cmd_plan.cpp
void add_validate_command(CLI::App& app);        ///< cmd_validate.cpp
void add_render_command(CLI::App& app);          ///< cmd_render.cpp
void add_bench_command(CLI::App& app);           ///< cmd_bench.cpp
void add_generate_objects_command(CLI::App& app);  ///< cmd_generate_objects.cpp
void add_merge_command(CLI::App& app);           ///< cmd_merge.cpp
void add_hand_command(CLI::App& app);            ///< cmd_hand.cpp
void add_export_command(CLI::App& app);          ///< cmd_export.cpp

}  // namespace cordgrasp::cli
