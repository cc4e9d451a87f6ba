// `cordgrasp run`: the main job — plan → validate (Bullet) → render, with report.md and .html.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <thread>

#include "commands.h"
#include "cordgrasp/core/error.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/object_meshes.h"
#include "cordgrasp/jobs/run_job.h"
#include "cordgrasp/jobs/validated_plan_job.h"
#include "options.h"
#include "validation_options.h"

namespace cordgrasp::cli {

void add_run_command(CLI::App& app) {
  struct Options {
    RunParams run;
    bool no_render = false;
    bool no_validate = false;
    bool quiet = false;
  };
  auto opt = std::make_shared<Options>();
  opt->run.hand = default_hand_name();
  opt->run.object = default_object_name();
  opt->run.job.plan.grasps = 3;
  opt->run.picture.size = "800x600";
  opt->run.jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  CLI::App* cmd = app.add_subcommand(
      "run", "The main job: plan grasps, check them in Bullet (lift, shake), render them, and "
             "write plan.json, sim.json, PNGs, report.md and report.html");
  cmd->add_option("--hand", opt->run.hand, "Hand description file or shipped hand name")
      ->capture_default_str();
  cmd->add_option("--object,-o", opt->run.object, "Object mesh file or shipped object name")
      ->capture_default_str();
  add_plan_job_options(cmd, opt->run.job);
  add_plan_settings_option(cmd, opt->run.job, opt->run.validation);
  add_enum_option(cmd, "--protocol", &opt->run.protocol, kProtocolHelp);
  cmd->add_option("--physics", opt->run.validation.physics_file, kPhysicsHelp);
  add_uncertainty_options(cmd, opt->run.validation);
  cmd->add_option("--tests", opt->run.tests,
                  "Physics tests: any of lift,shake,gravity6, or none (plan force-closure "
                  "grasps only)")
      ->check(physics_tests(true))
      ->capture_default_str();
  cmd->add_option(
         "--jobs,-j", opt->run.jobs,
         "Threads: a scan's set-up, the cord exploration's scans, and grasps simulated at once "
         "(one physics world each); results do not depend on it (default: the machine's cores)")
      ->check(whole_number_in(1, 256))
      ->capture_default_str();
  cmd->add_flag("--no-validate", opt->no_validate,
                "Plan force-closure grasps only and validate them afterwards (default: keep "
                "only grasps that hold in the settings' validation.min_held of "
                "validation.trials physics trials)");
  cmd->add_flag("--no-render", opt->no_render, "No pictures");
  cmd->add_flag("--quiet,-q", opt->quiet, "No progress on stderr");
  cmd->add_option("--out-dir", opt->run.out_dir, "Output folder (created if missing)")
      ->required();
  cmd->callback([opt]() {
    opt->run.render = !opt->no_render;
    opt->run.validate = !opt->no_validate;
    install_interrupt_handlers();
    opt->run.cancel = interrupt_token();
    const auto start = std::chrono::steady_clock::now();
    const RunOutcome out = run_job(opt->run, [&](const std::string& line) {
      if (opt->quiet) return;
      const double s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::fprintf(stderr, "run [%.1f s] %s\n", s, line.c_str());
    });
    std::cout << "run: " << out.report.plan.grasps.size() << " grasp(s) of "
              << out.report.plan.object_name << " with " << out.report.plan.hand_name;
    if (!out.sim_path.empty())
      std::cout << ", " << out.held << " held through " << to_string(out.report.sim->tests);
    if (const auto& v = out.report.plan.validation)
      std::cout << "\n  " << validation_stats_line(v->stats, out.report.plan.params.grasps);
    std::cout << "\n  report " << out.report_path << "\n  page   " << out.html_path << "\n";
    if (!out.report.interrupted.empty()) {
      std::cout << "run: interrupted by " << out.report.interrupted << " during "
                << out.report.interrupted_at << "; " << opt->run.out_dir
                << " holds what finished (report.md says where it stopped)\n";
      throw Interrupted("interrupted by " + out.report.interrupted);
    }
  });
}

}  // namespace cordgrasp::cli
