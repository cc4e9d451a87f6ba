// `cordgrasp validate`: physics validation (Bullet) of the grasps in a plan.json.
#include <cstdio>
#include <iostream>
#include <memory>
#include <tuple>

#include "commands.h"
#include "options.h"
#include "validation_options.h"
#include "cordgrasp/core/assets.h"
#include "cordgrasp/core/error.h"
#include "cordgrasp/jobs/physics_settings.h"
#include "cordgrasp/jobs/render_options.h"
#include "cordgrasp/jobs/text_format.h"
#include "cordgrasp/jobs/validate_job.h"
#include "cordgrasp/sim/sim_params.h"

namespace cordgrasp::cli {

void add_validate_command(CLI::App& app) {
  struct Options {
    ValidateJobParams job;
    bool quiet = false;
    bool print_physics = false;
  };
  auto opt = std::make_shared<Options>();
  auto video_size = std::make_shared<std::string>(std::to_string(VideoParams{}.width_px) + "x" +
                                                  std::to_string(VideoParams{}.height_px));
  CLI::App* cmd =
      app.add_subcommand("validate", "Check planned grasps in Bullet physics (lift, shake, "
                                     "gravity in six directions)");
  cmd->add_option("--plan", opt->job.plan, "plan.json written by `cordgrasp plan`")->required();
  cmd->add_option("--tests", opt->job.tests, "Tests to run after closing: lift,shake,gravity6")
      ->check(physics_tests(false))
      ->capture_default_str();
  add_enum_option(cmd, "--protocol", &opt->job.protocol,
                  kProtocolHelp);
  cmd->add_option("--mu", opt->job.mu, "Friction coefficient (default: the plan's μ)")
      ->check(settings_number("quality.contact.mu"));
  cmd->add_option("--mass", opt->job.physics.mass_kg,
                  "Object mass [kg] (default: the plan's validation record's, else from the "
                  "volume, docs/physics.md §2)")
      ->check(settings_number("validation.physics.mass_kg"));
  cmd->add_option("--physics", opt->job.physics_file, kPhysicsHelp);
  cmd->add_flag("--print-physics", opt->print_physics,
                "Print the settings this command would simulate with (YAML, a --physics file) "
                "and exit");
  cmd->add_option("--jobs,-j", opt->job.jobs,
                  "Grasps (and trials) simulated at once, one physics world per thread; the "
                  "results do not depend on it (--snapshots runs one at a time)")
      ->check(whole_number_in(1, 256))
      ->capture_default_str();
  CLI::Option* trials = cmd->add_option(
      "--trials", opt->job.trials,
                  "Simulate each grasp N times: as planned, then with the hand moved by " +
                      format_number(1e3 * PerturbationParams{}.offset_m) + " mm and turned by " +
                      format_number(1e3 * PerturbationParams{}.turn_rad) +
                      " mrad (held / not-held of marginal grasps is chaotic; docs/physics.md); "
                      "with an uncertainty model, the most uncertain draws per grasp (default: 1; "
                      "with a model, the plan's validation.max_draws or " +
                      std::to_string(HoldProbabilityParams{}.max_draws) + ")");
  trials->check(settings_whole_number("validation.trials"));
  cmd->add_option("--uncertainty", opt->job.uncertainty,
                  "P(held) of each grasp under uncertain hand pose, friction, mass, centre of "
                  "mass and grip force: none, realistic, or a JSON/YAML file of their spreads "
                  "(docs/physics.md §3b); draws until the 95 % interval is decided against "
                  "--min-hold-probability (default: the model the plan's grasps were accepted "
                  "under by plan --validate --uncertainty, else none)");
  cmd->add_option("--min-hold-probability", opt->job.min_hold_probability,
                  "Acceptance threshold of P(held) with an uncertainty model (default: the "
                  "plan's when the model is the plan's, else " +
                      format_number(HoldProbabilityParams{}.min_hold_probability) + ")")
      ->check(CLI::Range(0.01, 0.99));
  cmd->add_option("--seed", opt->job.seed, "Seed of the trials' random directions and draws")
      ->check(seed_value())
      ->capture_default_str();
  cmd->add_option("--trace", opt->job.trace_path,
                  "CSV of the object's shift [m] and turn [rad] in the hand and its contact count, "
                  "every trace_interval_s of simulated time (10 ms unless --physics sets it) and "
                  "at every phase end (first trial of each grasp)");
  cmd->add_option("--snapshots", opt->job.snapshots_dir,
                  "Existing folder: one PNG per grasp and phase end, grasp_K_<phase>.png");
  cmd->add_option("--video", opt->job.video_dir,
                  "Existing folder: one animated WebP of the physics per grasp, grasp_K.webp, "
                  "and per nudged trial, grasp_K_trial_T.webp, played in simulated time");
  cmd->add_option("--video-size", *video_size, "Animation frame size WxH [px]")
      ->capture_default_str();
  cmd->add_option("--video-fps", opt->job.video.frame_rate_hz, "Animation frames per second")
      ->check(CLI::Range(1.0, 100.0))
      ->capture_default_str();
  cmd->add_option("--out", opt->job.out, "Output sim.json (required unless --print-physics)");
  cmd->add_flag("--quiet,-q", opt->quiet, "No progress on stderr");
  cmd->callback([opt, video_size]() {
    std::tie(opt->job.video.width_px, opt->job.video.height_px) = parse_image_size(*video_size);
    if (opt->print_physics) {
      std::cout << physics_settings_yaml(validate_job_physics(opt->job));
      return;
    }
    if (opt->job.out.empty()) throw CLI::RequiredError("--out");
    ValidateJobCallbacks cb;
    cb.grasp_line = [](const std::string& line) { std::cout << line << '\n' << std::flush; };
    if (!opt->quiet)
      cb.progress = [](const std::string& stage, int done, int total) {
        if (stage == "animations")
          std::fprintf(stderr, "validate: animations %d/%d\n", done, total);
        else
          std::fprintf(stderr, "validate: %s%d/%d grasps\n",
                       stage == "grasps"             ? ""
                       : stage == "trials of grasps" ? "trials of "
                                                     : "P(held) of ",
                       done, total);
      };
    install_interrupt_handlers();
    opt->job.cancel = interrupt_token();
    const SimDocument doc = validate_job(opt->job, cb);
    std::cout << validation_summary(doc, opt->job.tests, opt->job.out);
    if (!doc.interrupted.empty()) {
      std::cout << "validate: interrupted by " << doc.interrupted << " after "
                << doc.results.size() << " of " << doc.grasps_asked
                << " grasps (every trial of each); " << opt->job.out
                << " holds those, marked incomplete\n";
      throw Interrupted("interrupted by " + doc.interrupted);
    }
  });
}

}  // namespace cordgrasp::cli
