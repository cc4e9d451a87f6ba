// `cordgrasp validate`: physics validation (Bullet) of the grasps in a plan.json.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>

#include "commands.h"
#include "options.h"
#include "validation_options.h"
#include "cordgrasp/core/assets.h"
#include "cordgrasp/core/error.h"
#include "cordgrasp/jobs/text_format.h"
#include "cordgrasp/jobs/validate_job.h"
#include "cordgrasp/sim/sim_params.h"

namespace cordgrasp::cli {

void add_validate_command(CLI::App& app) {
  struct Options {
    ValidateJobParams job;
    bool quiet = false;
  };
  auto opt = std::make_shared<Options>();
  const SimParams defaults;
  CLI::App* cmd =
      app.add_subcommand("validate", "Check planned grasps in Bullet physics (lift, shake, "
                                     "gravity in six directions)");
  cmd->add_option("--plan", opt->job.plan, "plan.json written by `cordgrasp plan`")->required();
  cmd->add_option("--hand", opt->job.hand,
                  "Hand (default: the plan's); a plan for another hand is an error");
  add_package_path_option(cmd, opt->job.hand_load);
  cmd->add_option("--object,-o", opt->job.object,
                  "Object mesh file or shipped object name (default: the plan's); another "
                  "object is an error");
  cmd->add_option("--units", opt->job.units, "Units of --object: m, mm or auto (default: the plan's)")
      ->check(one_of({"m", "mm", "auto"}));
  cmd->add_option_function<double>(
         "--scale", [opt](double s) { opt->job.scale = s; },
         "Scale of --object after --units (default: the plan's)")
      ->check(number_in(1e-6, 1000.0));
  cmd->add_option("--tests", opt->job.tests, "Tests to run after closing: lift,shake,gravity6")
      ->check(physics_tests(false))
      ->capture_default_str();
  add_enum_option(cmd, "--protocol", &opt->job.protocol,
                  kProtocolHelp);
  cmd->add_option("--mu", opt->job.mu, "Friction coefficient (default: the plan's μ)")
      ->check(number_in(0.0, 10.0));
  add_sim_override_options(cmd, opt->job.physics, "the plan's validation record's, else ");
  cmd->add_option("--object-shape", opt->job.object_shape,
                  "Object collision shape: auto, hull, decomposition, gimpact")
      ->check(one_of({"auto", "hull", "decomposition", "gimpact"}))
      ->capture_default_str();
  cmd->add_option("--physics", opt->job.physics_file,
                  "Physics settings JSON merged over the protocol (any SimParams fields, or a "
                  "sim.json whose parameters to repeat; docs/physics.md)");
  cmd->add_option("--cache-dir", opt->job.cache_dir,
                  "Directory caching convex decompositions on disk (by mesh hash)");
  cmd->add_option("--time-step", opt->job.time_step_s,
                  "Physics time step [s] (default 1/" +
                      std::to_string(std::lround(1.0 / defaults.time_step_s)) + ")")
      ->check(number_in(1e-5, 0.02));
  cmd->add_option("--solver-iterations", opt->job.solver_iterations,
                  "Constraint solver iterations per step (default " +
                      std::to_string(defaults.solver_iterations) + ")")
      ->check(whole_number_in(1, 10000));
  cmd->add_option("--contact-stiffness", opt->job.contact_stiffness_Npm,
                  "Finger-object contact stiffness [N/m] (default " +
                      format_number(defaults.contact_stiffness_Npm) + "; 0 = rigid contacts)")
      ->check(number_in(0.0, 1e9));
  cmd->add_option("--contact-damping", opt->job.contact_damping_Nspm,
                  "Finger-object contact damping [N s/m], with --contact-stiffness (default " +
                      format_number(defaults.contact_damping_Nspm) + ")")
      ->check(number_in(0.0, 1e7));
  cmd->add_option("--lift-hold", opt->job.lift_hold_s,
                  "Longest hold after the lift [s] (default: the protocol's)")
      ->check(number_in(0.0, 100.0));
  cmd->add_option("--shake-time", opt->job.shake_time_s,
                  "Time of each shake segment [s] (default: the protocol's)")
      ->check(number_in(1e-3, 100.0));
  cmd->add_option("--rock-time", opt->job.rock_time_s,
                  "Time of each rock segment [s] (default: the protocol's)")
      ->check(number_in(1e-3, 100.0));
  cmd->add_option("--rock-frequency", opt->job.rock_frequency_hz,
                  "Rock frequency [Hz]; at least one period per segment is used (default: the "
                  "protocol's)")
      ->check(number_in(1e-3, 100.0));
  cmd->add_option("--rest-exit-time", opt->job.rest_exit_time_s,
                  "The lift's hold ends once the object rested this long in the hand [s]; 0: "
                  "never (default: the protocol's)")
      ->check(number_in(0.0, 100.0));
  cmd->add_option("--shake-axes", opt->job.shake_axes,
                  "Shake and rock one axis after the other ('sequential') or along all three "
                  "at once ('together') (default: the protocol's)")
      ->check(CLI::IsMember({"sequential", "together"}));
  cmd->add_option("--squeeze", opt->job.squeeze_rad,
                  "Squeeze spring rest point past the planned joint values [rad] (default " +
                      format_number(defaults.squeeze_rad) + ")")
      ->check(number_in(0.0, 3.2));
  cmd->add_option("--squeeze-direction", opt->job.squeeze_direction,
                  std::string("Squeeze: 'actor' (every finger joint closes with its full "
                              "effort), 'contacts' (the joints press the planned contacts "
                              "along their normals with one common force) or 'balanced' (the "
                              "planned contacts are pressed by forces that cancel, so the "
                              "object stays where it was planned) (default ") +
                      to_string(defaults.squeeze_direction) + ")")
      ->check(one_of({"actor", "contacts", "balanced"}));
  cmd->add_option("--object-fixed", opt->job.object_fixed,
                  std::string("Hold the object in place while the hand closes, as if on a "
                              "support: 'never', during the 'reach' (let go when the squeeze "
                              "starts) or the whole 'close' (let go when the lift starts) "
                              "(default ") +
                      to_string(defaults.object_fixed) + ")")
      ->check(one_of({"never", "reach", "close"}));
  cmd->add_option("--effort-scale", opt->job.effort_scale,
                  "Multiply every joint effort limit (e.g. 0.5 for weaker motors)")
      ->check(number_in(1e-3, 100.0));
  cmd->add_option("--concavity", opt->job.concavity,
                  "HACD: largest concavity of a part, fraction of the bounding-box diagonal")
      ->check(number_in(0.0, 1.0));
  cmd->add_option("--hacd-triangles", opt->job.hacd_triangles,
                  "HACD: decompose a vertex-clustered copy of at most this many triangles "
                  "(0 = the mesh itself)")
      ->check(whole_number_in(0, 10000000));
  cmd->add_option("--hull-vertices", opt->job.hull_vertices,
                  "Most vertices of each object hull (the single hull or a decomposition part; "
                  "default " +
                      std::to_string(defaults.decomposition.max_hull_vertices) + ")")
      ->check(whole_number_in(4, 100000));
  cmd->add_flag("--warmstart", opt->job.warmstart,
                "Warm-start the hand's contact impulses from the previous step (Bullet's "
                "articulated warmstarting)");
  cmd->add_option("--jobs,-j", opt->job.jobs,
                  "Grasps (and trials) simulated at once, one physics world per thread; the "
                  "results do not depend on it (--snapshots runs one at a time)")
      ->check(whole_number_in(1, 256))
      ->capture_default_str();
  cmd->add_option("--grasps", opt->job.grasps, "Validate only the first K grasps of the plan")
      ->check(whole_number_in(1, 100000));
  cmd->add_option("--trials", opt->job.trials,
                  "Simulate each grasp N times: as planned, then with the hand moved by "
                  "--trial-offset and turned by --trial-turn (held / not-held of marginal "
                  "grasps is chaotic; docs/physics.md)")
      ->check(whole_number_in(1, 1000))
      ->capture_default_str();
  cmd->add_option("--trial-offset", opt->job.perturbation.offset_m,
                  "Hand offset of the repeated trials [m], random direction")
      ->check(number_in(0.0, 0.1))
      ->capture_default_str();
  cmd->add_option("--trial-turn", opt->job.perturbation.turn_rad,
                  "Hand turn of the repeated trials about the GCP [rad], random axis")
      ->check(number_in(0.0, 0.5))
      ->capture_default_str();
  cmd->add_option("--seed", opt->job.seed, "Seed of the trials' random directions")
      ->check(seed_value())
      ->capture_default_str();
  cmd->add_option("--trace", opt->job.trace_path,
                  "CSV of the object's shift [m] and turn [rad] in the hand and its contact count, "
                  "every --trace-interval of simulated time and at every phase end (first trial "
                  "of each grasp)");
  cmd->add_option("--trace-interval", opt->job.trace_interval_s,
                  "Simulated time between --trace rows [s]")
      ->check(number_in(1e-4, 10.0))
      ->capture_default_str();
  cmd->add_option("--snapshots", opt->job.snapshots_dir,
                  "Existing folder: one PNG per grasp and phase end, grasp_K_<phase>.png");
  cmd->add_option("--out", opt->job.out, "Output sim.json")->required();
  cmd->add_flag("--quiet,-q", opt->quiet, "No progress on stderr");
  cmd->callback([opt]() {
    if (!opt->job.object.empty()) opt->job.object = resolve_object_path(opt->job.object);
    ValidateJobCallbacks cb;
    cb.grasp_line = [](const std::string& line) { std::cout << line << '\n' << std::flush; };
    if (!opt->quiet)
      cb.progress = [](const std::string& stage, int done, int total) {
        std::fprintf(stderr, "validate: %s%d/%d grasps\n",
                     stage == "grasps" ? "" : "trials of ", done, total);
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
