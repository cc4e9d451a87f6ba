// `cordgrasp render`: offscreen pictures (OSMesa) of objects, hands and plans, as PNG.
#include <iostream>
#include <memory>

#include "commands.h"
#include "cordgrasp/core/assets.h"
#include "cordgrasp/jobs/render_job.h"
#include "options.h"

namespace cordgrasp::cli {

void add_render_command(CLI::App& app) {
  auto opt = std::make_shared<RenderJobParams>();
  CLI::App* cmd = app.add_subcommand(
      "render", "Render plans, grasp regions, hands or objects to PNG offscreen");
  cmd->add_option("--object,-o", opt->objects,
                  "Object mesh file or shipped object name to show; several: a contact sheet, --size "
                  "per tile");
  cmd->add_option(
      "--hand", opt->hand,
      "Hand description (YAML) or shipped hand name: the hand alone, root at the origin");
  add_package_path_option(cmd, opt->hand_load);
  cmd->add_option("--close", opt->close,
                  "With --hand: close every actor joint this fraction of the way to its limit")
      ->check(number_in(0.0, 1.0));
  cmd->add_option("--joint", opt->joints, "With --hand: set a joint, NAME=VALUE (rad or m)");
  cmd->add_flag("--collision", opt->collision, "Also show collision shapes (translucent)");
  cmd->add_flag("--no-visual", opt->no_visual, "With --collision: collision shapes only");
  cmd->add_option("--plan", opt->plan,
                  "plan.json from `cordgrasp plan`: a grasp with the hand, its contacts and its "
                  "region's cords");
  cmd->add_option("--grasp", opt->grasp, "With --plan: which grasp (0 = first, as plan prints)")
      ->check(whole_number_at_least(0))
      ->capture_default_str();
  cmd->add_flag("--cones", opt->cones,
                "With --plan: friction cones (half-angle atan mu) instead of normal arrows");
  cmd->add_flag("--no-cords", opt->no_cords,
                "With --plan: no cords (skips replaying the cord exploration)");
  cmd->add_option("--regions", opt->regions,
                  "Grasp regions from `cordgrasp explore --json`: the object with a region's "
                  "front cords and P1 (dark), P_l (magenta), P_r (teal)");
  cmd->add_option("--region", opt->region, "With --regions: which region, by rank (1 = best)")
      ->check(whole_number_at_least(1))
      ->capture_default_str();
  cmd->add_option("--sheet", opt->sheet,
                  "With --plan or --regions: the first N as a contact sheet, --size per tile")
      ->check(whole_number_at_least(1));
  cmd->add_option("--units", opt->units, "Units of the object file: m, mm or auto")
      ->check(one_of({"m", "mm", "auto"}))
      ->capture_default_str();
  add_scale_option(cmd, &opt->scale, " (a plan is drawn at its own scale)");
  add_picture_options(*cmd, opt->picture);
  cmd->add_option("--out", opt->out, "Output PNG file")->required();
  cmd->callback([opt]() {
    for (std::string& object : opt->objects) object = resolve_object_path(object);
    std::cout << render_job(*opt, [](const std::string& w) {
      std::cerr << "cordgrasp: warning: " << w << '\n';
    }) << '\n';
  });
}

}  // namespace cordgrasp::cli
