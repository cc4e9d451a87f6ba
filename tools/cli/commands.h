#pragma once
#include <CLI/CLI.hpp>

namespace cordgrasp::cli {

/// Each adds one subcommand (with its options and callback) to the cordgrasp app.
void add_info_command(CLI::App& app);

}  // namespace cordgrasp::cli
