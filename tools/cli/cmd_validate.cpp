// `cordgrasp validate`: physics validation (Bullet) of the grasps in a plan.json (issue 5).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

#include "commands.h"
#include "cordgrasp/core/atomic_file.h"
#include "cordgrasp/core/error.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/sim/convex_decomposition.h"
#include "cordgrasp/render/renderer.h"
#include "cordgrasp/jobs/hand_scene.h"
#include "cordgrasp/jobs/plan_job.h"
#include "cordgrasp/jobs/plan_json.h"
#include "cordgrasp/jobs/render_options.h"
#include "cordgrasp/jobs/sim_json.h"
#include "cordgrasp/jobs/text_format.h"

namespace cordgrasp::cli {
namespace {

struct ValidateOptions {
  std::string plan;
  std::string hand;
  std::string object;
  std::string units;
  std::string tests = "lift,shake,gravity6";
  std::optional<double> mu;
  std::optional<double> mass_kg;
  std::optional<double> density_kgm3;
  std::string object_shape = "auto";
  std::string cache_dir;
  std::optional<double> time_step_s;
  std::optional<int> solver_iterations;
  std::optional<double> contact_stiffness_Npm;
  std::optional<double> contact_damping_Nspm;
  std::optional<double> concavity;
  std::optional<double> squeeze_rad;
  std::string squeeze_direction;
  std::optional<double> effort_scale;
  std::optional<int> hacd_triangles;
  std::optional<int> hull_vertices;
  bool warmstart = false;
  int grasps = -1;
  int trials = 1;
  PerturbationParams perturbation;
  std::uint64_t seed = 1;
  std::string snapshots_dir;
  std::string trace_path;
  double trace_interval_s = 0.01;
  std::string out;
  bool quiet = false;
};

std::string canonical(const std::string& path) {
  std::error_code ec;
  const auto p = std::filesystem::weakly_canonical(path, ec);
  return ec ? path : p.string();
}

void run_validate(const ValidateOptions& opt) {
  // Output folders are checked before minutes of simulation, not after.
  check_output_file(opt.out);
  if (!opt.trace_path.empty()) check_output_file(opt.trace_path);
  const nlohmann::json plan_json = read_plan_json(opt.plan);
  // Hand: the plan's, or the one given (which must be the plan's).
  const std::string hand_path = opt.hand.empty() ? plan_hand_path(plan_json) : opt.hand;
  const HandModel hand = load_hand(hand_path);
  const PlanDocument plan = plan_from_json(plan_json, hand, opt.plan);  // throws for another hand

  // Object: the plan's, or the one given (which must be the plan's geometry).
  MeshLoadOptions mesh_opt;
  mesh_opt.units = parse_length_units(opt.units.empty() ? plan.object_units : opt.units);
  Mesh mesh;
  if (opt.object.empty()) {
    mesh = load_mesh(plan.object_path, mesh_opt);
  } else {
    mesh = load_mesh(opt.object, mesh_opt);
    if (canonical(opt.object) != canonical(plan.object_path)) {
      bool same = false;
      if (std::filesystem::exists(plan.object_path))
        same = mesh_hash(load_mesh(plan.object_path, mesh_opt)) == mesh_hash(mesh);
      else
        same = plan.object_triangles == static_cast<int>(mesh.triangles.size());
      if (!same)
        throw InputError("validate: '" + opt.plan + "' was planned for object '" +
                         plan.object_path + "', not '" + opt.object + "'");
    }
  }

  SimParams params;
  // μ: one value shared with the planner: the plan's unless --mu overrides it.
  params.contact = plan_contact_model(plan);
  if (opt.mu) params.contact.mu = *opt.mu;
  if (opt.mass_kg) params.mass_kg = *opt.mass_kg;
  if (opt.density_kgm3) params.density_kgm3 = *opt.density_kgm3;
  params.object_shape = parse_object_shape(opt.object_shape);
  params.decomposition_cache_dir = opt.cache_dir;
  if (opt.time_step_s) params.time_step_s = *opt.time_step_s;
  if (opt.solver_iterations) params.solver_iterations = *opt.solver_iterations;
  if (opt.contact_stiffness_Npm) params.contact_stiffness_Npm = *opt.contact_stiffness_Npm;
  if (opt.contact_damping_Nspm) params.contact_damping_Nspm = *opt.contact_damping_Nspm;
  if (opt.squeeze_rad) params.squeeze_rad = *opt.squeeze_rad;
  if (!opt.squeeze_direction.empty())
    params.squeeze_direction = parse_squeeze_direction(opt.squeeze_direction);
  if (opt.effort_scale) params.effort_scale = *opt.effort_scale;
  if (opt.concavity) params.decomposition.concavity = *opt.concavity;
  if (opt.hacd_triangles) params.decomposition.max_input_triangles = *opt.hacd_triangles;
  if (opt.hull_vertices) params.decomposition.max_hull_vertices = *opt.hull_vertices;
  if (opt.warmstart) params.articulated_warmstarting = true;
  const SimTests tests = sim_tests_from_string(opt.tests);

  const bool progress = !opt.quiet;
  // --snapshots: the world at the end of every phase (not of shake / gravity6 segments).
  const auto object = std::make_shared<const Mesh>(mesh);
  std::vector<SnapshotFrame> frames;
  std::unique_ptr<Renderer> renderer;
  if (!opt.snapshots_dir.empty()) {
    if (!std::filesystem::is_directory(opt.snapshots_dir))
      throw InputError("validate: --snapshots '" + opt.snapshots_dir + "' is not a directory");
    renderer = std::make_unique<Renderer>();
  }
  // --trace: the object in the hand every trace_interval_s and at every phase end, as CSV.
  std::ostringstream trace;
  if (!opt.trace_path.empty()) {
    params.trace_interval_s = opt.trace_interval_s;
    trace << "grasp,phase,phase_end,sim_time_s,object_shift_m,object_turn_rad,contacts\n";
  }
  const auto hooks = [&](int k) -> PhaseHook {
    if (!renderer && opt.trace_path.empty()) return {};
    return [&, k](const PhaseSnapshot& s) {
      if (!opt.trace_path.empty())
        trace << k << ',' << s.phase << ',' << (s.phase_end ? 1 : 0) << ','
              << format_number(s.sim_time_s) << ',' << format_number(s.object_shift_m) << ','
              << format_number(s.object_turn_rad) << ',' << s.contact_count << '\n';
      // Pictures at phase ends only, not of trace samples or segments (e.g. "shake x").
      if (!renderer || !s.phase_end || s.phase.find(' ') != std::string::npos) return;
      frames.push_back({s.X_WL, s.X_WO, "", s.phase});
    };
  };
  SimDocument doc = validate_plan(
      plan, hand, mesh, params, tests, opt.grasps,
      [&](int done, int total, const SimResult& r) {
        std::cout << "grasp " << done - 1 << ": " << sim_result_line(r) << '\n' << std::flush;
        if (renderer) {
          for (SnapshotFrame& f : frames) {
            const PhaseResult* p = r.phase(f.name);
            f.caption = plan.object_name + " · " + hand.name + " · grasp " +
                        std::to_string(done - 1) + " · after " + f.name +
                        (p ? std::string(" · ") + to_string(p->outcome) : std::string());
          }
          RenderParams picture;
          picture.width_px = 800;
          picture.height_px = 600;
          write_snapshots(*renderer, hand, object, frames, opt.snapshots_dir,
                          "grasp_" + std::to_string(done - 1), picture);
          frames.clear();
        }
        if (progress) std::fprintf(stderr, "validate: %d/%d grasps\n", done, total);
      },
      hooks);
  if (opt.trials > 1)
    add_perturbed_trials(doc, plan, hand, mesh, opt.trials, opt.perturbation, opt.seed,
                         [&](int done, int total, const SimResult&) {
                           std::cout << "grasp " << done - 1 << ": "
                                     << trials_line(doc.trial_outcomes[static_cast<size_t>(done - 1)])
                                     << '\n' << std::flush;
                           if (progress)
                             std::fprintf(stderr, "validate: trials of %d/%d grasps\n", done, total);
                         });
  doc.plan_path = canonical(opt.plan);
  doc.object_path = opt.object.empty() ? plan.object_path : canonical(opt.object);
  if (!opt.trace_path.empty()) write_file_atomically(opt.trace_path, trace.str());
  write_sim_file(opt.out, doc, hand);
  int held = 0;
  for (const SimResult& r : doc.results) held += r.held();
  std::printf("held %d / %d (tests %s, mu %.3g) -> %s\n", held,
              static_cast<int>(doc.results.size()), opt.tests.c_str(), params.contact.mu,
              opt.out.c_str());
  std::printf("%s\n", failures_line(doc.results).c_str());
  if (!doc.trial_outcomes.empty()) {
    std::vector<Outcome> all;
    for (const auto& t : doc.trial_outcomes) all.insert(all.end(), t.begin(), t.end());
    std::printf("%s of all grasps\n", trials_line(all).c_str());
  }
}

}  // namespace


void add_validate_command(CLI::App& app) {
  auto opt = std::make_shared<ValidateOptions>();
  const SimParams defaults;
  CLI::App* cmd =
      app.add_subcommand("validate", "Check planned grasps in Bullet physics (lift, shake, "
                                     "gravity in six directions)");
  cmd->add_option("--plan", opt->plan, "plan.json written by `cordgrasp plan`")->required();
  cmd->add_option("--hand", opt->hand,
                  "Hand (default: the plan's); a plan for another hand is an error");
  cmd->add_option("--object,-o", opt->object,
                  "Object mesh (default: the plan's); another object is an error");
  cmd->add_option("--units", opt->units, "Units of --object: m, mm or auto (default: the plan's)")
      ->check(CLI::IsMember({"m", "mm", "auto"}));
  cmd->add_option("--tests", opt->tests, "Tests to run after closing: lift,shake,gravity6")
      ->capture_default_str();
  cmd->add_option("--mu", opt->mu, "Friction coefficient (default: the plan's μ)");
  cmd->add_option("--mass", opt->mass_kg, "Object mass [kg] (default: density × volume)");
  cmd->add_option("--density", opt->density_kgm3,
                  "Object density [kg/m^3] (default " + format_number(defaults.density_kgm3) + ")");
  cmd->add_option("--object-shape", opt->object_shape,
                  "Object collision shape: auto, hull, decomposition, gimpact")
      ->check(CLI::IsMember({"auto", "hull", "decomposition", "gimpact"}))
      ->capture_default_str();
  cmd->add_option("--cache-dir", opt->cache_dir,
                  "Directory caching convex decompositions on disk (by mesh hash)");
  cmd->add_option("--time-step", opt->time_step_s,
                  "Physics time step [s] (default 1/" +
                      std::to_string(std::lround(1.0 / defaults.time_step_s)) + ")")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--solver-iterations", opt->solver_iterations,
                  "Constraint solver iterations per step (default " +
                      std::to_string(defaults.solver_iterations) + ")")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--contact-stiffness", opt->contact_stiffness_Npm,
                  "Finger-object contact stiffness [N/m] (default " +
                      format_number(defaults.contact_stiffness_Npm) + "; 0 = rigid contacts)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--contact-damping", opt->contact_damping_Nspm,
                  "Finger-object contact damping [N s/m], with --contact-stiffness (default " +
                      format_number(defaults.contact_damping_Nspm) + ")")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--squeeze", opt->squeeze_rad,
                  "Squeeze spring rest point past the planned joint values [rad] (default " +
                      format_number(defaults.squeeze_rad) + ")");
  cmd->add_option("--squeeze-direction", opt->squeeze_direction,
                  std::string("Squeeze: 'actor' (every finger joint closes with its full "
                              "effort) or 'contacts' (the joints press the planned contacts "
                              "along their normals with one common force) (default ") +
                      to_string(defaults.squeeze_direction) + ")")
      ->check(CLI::IsMember({"actor", "contacts"}));
  cmd->add_option("--effort-scale", opt->effort_scale,
                  "Multiply every joint effort limit (e.g. 0.5 for weaker motors)");
  cmd->add_option("--concavity", opt->concavity,
                  "HACD: largest concavity of a part, fraction of the bounding-box diagonal");
  cmd->add_option("--hacd-triangles", opt->hacd_triangles,
                  "HACD: decompose a vertex-clustered copy of at most this many triangles "
                  "(0 = the mesh itself)");
  cmd->add_option("--hull-vertices", opt->hull_vertices,
                  "Most vertices of each object hull (the single hull or a decomposition part; "
                  "default " +
                      std::to_string(defaults.decomposition.max_hull_vertices) + ")")
      ->check(CLI::Range(4, 100000));
  cmd->add_flag("--warmstart", opt->warmstart,
                "Warm-start the hand's contact impulses from the previous step (Bullet's "
                "articulated warmstarting)");
  cmd->add_option("--grasps", opt->grasps, "Validate only the first K grasps of the plan");
  cmd->add_option("--trials", opt->trials,
                  "Simulate each grasp N times: as planned, then with the hand moved by "
                  "--trial-offset and turned by --trial-turn (held / not-held of marginal "
                  "grasps is chaotic; docs/physics.md)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  cmd->add_option("--trial-offset", opt->perturbation.offset_m,
                  "Hand offset of the repeated trials [m], random direction")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--trial-turn", opt->perturbation.turn_rad,
                  "Hand turn of the repeated trials about the GCP [rad], random axis")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--seed", opt->seed, "Seed of the trials' random directions")
      ->capture_default_str();
  cmd->add_option("--trace", opt->trace_path,
                  "CSV of the object's shift [m] and turn [rad] in the hand and its contact count, "
                  "every --trace-interval of simulated time and at every phase end (first trial "
                  "of each grasp)");
  cmd->add_option("--trace-interval", opt->trace_interval_s,
                  "Simulated time between --trace rows [s]")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--snapshots", opt->snapshots_dir,
                  "Existing folder: one PNG per grasp and phase end, grasp_K_<phase>.png");
  cmd->add_option("--out", opt->out, "Output sim.json")->required();
  cmd->add_flag("--quiet,-q", opt->quiet, "No progress on stderr");
  cmd->callback([opt]() { run_validate(*opt); });
}

}  // namespace cordgrasp::cli
