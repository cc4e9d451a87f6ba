#pragma once
#include <CLI/CLI.hpp>

namespace cordgrasp::cli {

/// Adds one subcommand (options and callback) to the cordgrasp app.
using CommandAdder = void (*)(CLI::App& app);

/// Registers a subcommand; `order` sets its place in --help. Use CORDGRASP_REGISTER_COMMAND.
bool register_command(int order, CommandAdder adder);

/// Adds every registered subcommand to `app`, in ascending order.
void add_registered_commands(CLI::App& app);

}  // namespace cordgrasp::cli

/// In a cmd_*.cpp file: CORDGRASP_REGISTER_COMMAND(10, add_info_command);
#define CORDGRASP_REGISTER_COMMAND(order, adder) \
  static const bool adder##_registered = ::cordgrasp::cli::register_command(order, adder)
