#include "commands.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace cordgrasp::cli {
namespace {
std::vector<std::pair<int, CommandAdder>>& registry() {
  static std::vector<std::pair<int, CommandAdder>> commands;
  return commands;
}
}  // namespace

bool register_command(int order, CommandAdder adder) {
  registry().emplace_back(order, adder);
  return true;
}

void add_registered_commands(CLI::App& app) {
  auto commands = registry();
  std::stable_sort(commands.begin(), commands.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [order, adder] : commands) adder(app);
}

}  // namespace cordgrasp::cli
