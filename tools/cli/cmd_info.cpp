// `cordgrasp info`: human or JSON summary of an object mesh or a hand model.
#include <iostream>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "options.h"
#include "cordgrasp/jobs/info.h"

namespace cordgrasp::cli {
namespace {

struct InfoOptions {
  std::string object;
  std::string hand;
  HandLoadOptions hand_load;
  std::string units = "m";
  double scale = 1.0;
  bool json = false;
};

}  // namespace


void add_info_command(CLI::App& app) {
  auto opt = std::make_shared<InfoOptions>();
  CLI::App* cmd = app.add_subcommand("info", "Summarize an object mesh or a hand model");
  cmd->add_option("--object,-o", opt->object, "Object mesh file (OBJ, STL, PLY, OFF, DAE, glTF)");
  cmd->add_option("--hand", opt->hand,
                  "Hand description (YAML) or the name of a shipped hand, e.g. cordgrasp_sah");
  add_package_path_option(cmd, opt->hand_load);
  cmd->add_option("--units", opt->units, "Units of the object file: m, mm or auto")
      ->check(one_of({"m", "mm", "auto"}))
      ->capture_default_str();
  add_scale_option(cmd, &opt->scale);
  cmd->add_flag("--json", opt->json, "Print machine-readable JSON instead of text");
  cmd->callback([opt]() {
    if (opt->object.empty() == opt->hand.empty())
      throw CLI::ValidationError("info", "give exactly one of --object FILE or --hand HAND");
    if (!opt->hand.empty()) {
      const nlohmann::json j = hand_info_json(opt->hand, opt->hand_load);
      if (opt->json)
        std::cout << j.dump(2) << '\n';
      else
        print_hand_info(j);
      return;
    }
    const nlohmann::json j = object_info_json(opt->object, opt->units, opt->scale);
    if (opt->json)
      std::cout << j.dump(2) << '\n';
    else
      print_object_info(j);
  });
}

}  // namespace cordgrasp::cli
