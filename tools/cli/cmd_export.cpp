// `cordgrasp export`: a plan's grasps as a MuJoCo scene, moveit_msgs/Grasp YAML or meshes.
#include <iostream>
#include <memory>

#include "commands.h"
#include "cordgrasp/jobs/export_job.h"
#include "options.h"
#include "validation_options.h"

namespace cordgrasp::cli {

void add_export_command(CLI::App& app) {
  auto opt = std::make_shared<ExportJobParams>();
  CLI::App* cmd = app.add_subcommand(
      "export", "Write a plan's grasps for other tools: MuJoCo scene (mjcf), moveit_msgs/Grasp "
                "YAML (moveit), posed meshes (glb, obj); docs/export.md");
  cmd->add_option("--plan", opt->plan, "plan.json written by `cordgrasp plan`")->required();
  cmd->add_option_function<std::string>(
         "--format", [opt](const std::string& t) { opt->format = parse_export_format(t); },
         "mjcf (MuJoCo scene, one keyframe per grasp), moveit (moveit_msgs/Grasp list), glb "
         "or obj (one mesh file per grasp)")
      ->check(one_of({"mjcf", "moveit", "glb", "obj"}))
      ->required();
  cmd->add_option("--out", opt->out,
                  "mjcf, moveit: the file to write; glb, obj: a folder for grasp_K.<ext>")
      ->required();
  cmd->add_option("--grasps", opt->grasps, "Export only the first K grasps of the plan")
      ->check(whole_number_in(0, 100000));
  cmd->add_option("--cache-dir", opt->cache_dir,
                  "mjcf: directory caching the object's convex decomposition (by mesh hash)");
  // mjcf: the object's weight and grip of the exported bounded close, as `validate` takes them.
  add_sim_override_options(cmd, opt->physics, "the plan's validation record's, else ");
  add_package_path_option(cmd, opt->hand_load);
  cmd->callback([opt]() {
    const ExportOutcome out = export_job(*opt);
    std::cout << "export: " << out.grasps << " grasp(s) as " << to_string(opt->format)
              << (out.files.empty() ? ", nothing written" : ", wrote " + out.files.front());
    if (out.files.size() > 1) std::cout << " (+" << out.files.size() - 1 << " files)";
    std::cout << '\n';
  });
}

}  // namespace cordgrasp::cli
