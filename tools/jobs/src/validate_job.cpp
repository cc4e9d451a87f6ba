#include "cordgrasp/jobs/validate_job.h"

#include <algorithm>
#include <filesystem>
#include <memory>
#include <sstream>

#include "cordgrasp/core/atomic_file.h"
#include "cordgrasp/core/assets.h"
#include "cordgrasp/core/error.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/jobs/hand_scene.h"
#include "cordgrasp/jobs/physics_settings.h"
#include "cordgrasp/jobs/plan_job.h"
#include "cordgrasp/jobs/plan_json.h"
#include "cordgrasp/jobs/render_options.h"
#include "cordgrasp/jobs/sim_json.h"
#include "cordgrasp/jobs/text_format.h"
#include "cordgrasp/jobs/uncertainty_settings.h"
#include "cordgrasp/render/renderer.h"
#include "cordgrasp/sim/convex_decomposition.h"

namespace cordgrasp {
namespace {

std::string canonical(const std::string& path) {
  std::error_code ec;
  const auto p = std::filesystem::weakly_canonical(path, ec);
  return ec ? path : p.string();
}

SimParams physics_for_plan(const ValidateJobParams& opt, const PlanDocument& plan) {
  PhysicsChoice choice;
  choice.protocol = opt.protocol;
  choice.mu = opt.mu;
  choice.overrides = opt.physics;
  if (plan.validation) choice.recorded = plan.validation->params.physics;
  choice.cache_dir = opt.cache_dir;
  // The settings file given, else the one a validated plan was accepted with.
  choice.file = !opt.physics_file.empty() || !plan.validation
                    ? opt.physics_file
                    : plan.validation->params.physics_file;
  return physics_settings(plan_contact_model(plan), choice);
}

// The P(held) test of a validate run: the uncertainty model, draws per grasp and threshold
// given, else the plan's (a plan accepted under uncertainty), else the defaults. max_draws is
// the trials per grasp also without uncertainty (1 unless --trials).
struct HoldTest {
  UncertaintyParams uncertainty;
  HoldProbabilityParams test;
};

HoldTest hold_test_for(const ValidateJobParams& opt, const PlanDocument& plan) {
  const bool plan_model = opt.uncertainty.empty() && plan.validation &&
                          !is_none(plan.validation->params.uncertainty);
  const HoldProbabilityParams defaults;
  const int plan_draws = plan_model ? plan.validation->params.max_draws : defaults.max_draws;
  const double plan_threshold = plan_model ? plan.validation->params.min_hold_probability
                                           : defaults.min_hold_probability;
  HoldTest out;
  out.uncertainty = plan_model ? plan.validation->params.uncertainty
                               : uncertainty_settings(opt.uncertainty.empty() ? "none"
                                                                              : opt.uncertainty);
  const bool uncertain = !is_none(out.uncertainty);
  const int trials = opt.trials > 0 ? opt.trials : uncertain ? plan_draws : 1;
  const double threshold =
      opt.min_hold_probability > 0.0 ? opt.min_hold_probability : plan_threshold;
  out.test = hold_test_params(threshold, trials, opt.seed);
  if (uncertain) {
    try {
      check_hold_test(out.uncertainty, out.test);
    } catch (const std::invalid_argument& e) {
      throw InputError(std::string("validate: --min-hold-probability / --trials: ") + e.what());
    }
  }
  return out;
}

}  // namespace

SimParams validate_job_physics(const ValidateJobParams& opt) {
  const nlohmann::json plan_json = read_plan_json(opt.plan);
  const HandModel hand =
      load_hand(opt.hand.empty() ? plan_hand_path(plan_json) : opt.hand, opt.hand_load);
  return physics_for_plan(opt, plan_from_json(plan_json, hand, opt.plan));
}

SimDocument validate_job(const ValidateJobParams& opt, const ValidateJobCallbacks& cb) {
  // Output folders are checked before minutes of simulation, not after.
  check_output_file(opt.out);
  if (!opt.trace_path.empty()) check_output_file(opt.trace_path);
  if (!opt.video_dir.empty() && !std::filesystem::is_directory(opt.video_dir))
    throw InputError("validate: --video '" + opt.video_dir + "' is not a directory");
  if (!opt.cache_dir.empty() && !std::filesystem::is_directory(opt.cache_dir))
    throw InputError("validate: --cache-dir '" + opt.cache_dir + "' is not a directory");
  const nlohmann::json plan_json = read_plan_json(opt.plan);
  // Hand: the plan's, or the one given (which must be the plan's).
  const std::string hand_path = opt.hand.empty() ? plan_hand_path(plan_json) : opt.hand;
  const HandModel hand = load_hand(hand_path, opt.hand_load);
  const PlanDocument plan = plan_from_json(plan_json, hand, opt.plan);  // throws for another hand
  SimParams params = physics_for_plan(opt, plan);  // settings errors before the mesh is read
  const HoldTest hold = hold_test_for(opt, plan);
  const bool uncertain = !is_none(hold.uncertainty);
  const int trials = hold.test.max_draws;  // per grasp, with or without uncertainty

  // Object: the plan's, or the one given (which must be the plan's geometry).
  const MeshLoadOptions mesh_opt =
      job_mesh_load_options(parse_length_units(opt.units.empty() ? plan.object_units : opt.units),
                            opt.scale.value_or(plan.object_scale));
  Mesh mesh;
  if (opt.object.empty()) {
    mesh = load_mesh(resolve_object_path(plan.object_path), mesh_opt);  // or a shipped name
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

  const SimTests tests = sim_tests_from_string(opt.tests);

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
    if (!(params.trace_interval_s > 0.0)) params.trace_interval_s = kDefaultTraceInterval_s;
    trace << "grasp,phase,phase_end,sim_time_s,object_shift_m,object_turn_rad,contacts\n";
  }
  // --video: every sample of the phases, one frame each, animated after the physics.
  const bool video = !opt.video_dir.empty();
  if (video) params.trace_interval_s = 1.0 / opt.video.frame_rate_hz;
  std::vector<std::vector<PhaseSnapshot>> samples(video ? plan.grasps.size() : 0);
  std::vector<std::string> trace_rows(plan.grasps.size());
  const auto hooks = [&](int k) -> PhaseHook {
    if (!renderer && opt.trace_path.empty() && !video) return {};
    return [&, k](const PhaseSnapshot& s) {
      if (video) samples[static_cast<size_t>(k)].push_back(s);
      if (!opt.trace_path.empty())  // each grasp's rows apart: grasps may run on threads
        trace_rows[static_cast<size_t>(k)] +=
            std::to_string(k) + ',' + s.phase + ',' + (s.phase_end ? "1" : "0") + ',' +
            format_number(s.sim_time_s) + ',' + format_number(s.object_shift_m) + ',' +
            format_number(s.object_turn_rad) + ',' + std::to_string(s.contact_count) + '\n';
      // Pictures at phase ends only, not of trace samples or segments (e.g. "shake x").
      if (!renderer || !s.phase_end || s.phase.find(' ') != std::string::npos) return;
      frames.push_back({s.X_WL, s.X_WO, "", s.phase});
    };
  };
  SimDocument doc = validate_plan(
      plan, hand, mesh, params, tests, opt.grasps,
      [&](int done, int total, const SimResult& r) {
        if (cb.grasp_line)
          cb.grasp_line("grasp " + std::to_string(done - 1) + ": " + sim_result_line(r));
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
        if (cb.progress) cb.progress("grasps", done, total);
      },
      hooks, renderer ? 1 : opt.jobs,  // pictures are drawn on this thread, one grasp at a time
      opt.cancel);
  const int asked = doc.grasps_asked;
  // --video: each trial's samples and result too, by [result index][trial].
  std::vector<std::vector<std::vector<PhaseSnapshot>>> trial_samples;
  const std::vector<int> trial_index = doc.grasp_indices;  // results' grasps before the trials
  std::vector<std::vector<SimResult>> trial_results;
  TrialWatch watch;
  if (video && trials > 1 && !uncertain) {
    trial_samples.assign(doc.results.size(), std::vector<std::vector<PhaseSnapshot>>(
                                                 static_cast<size_t>(trials)));
    trial_results.assign(doc.results.size(), std::vector<SimResult>(size_t(trials)));
    watch.hook = [&](int k, int t) -> PhaseHook {
      return [&, k, t](const PhaseSnapshot& s) {
        trial_samples[size_t(k)][size_t(t)].push_back(s);
      };
    };
    watch.done = [&](int k, int t, const SimResult& r) { trial_results[size_t(k)][size_t(t)] = r; };
  }
  if (uncertain)  // P(held): the draws of each grasp in order until its test is decided
    add_hold_probabilities(doc, plan, hand, mesh, hold.uncertainty, hold.test,
                           [&](int done, int total, const SimResult&) {
                             if (cb.grasp_line)
                               cb.grasp_line("grasp " + std::to_string(done - 1) + ": " +
                                             hold_probability_line(doc.hold_probabilities[
                                                 static_cast<size_t>(done - 1)]));
                             if (cb.progress) cb.progress("P(held) of grasps", done, total);
                           },
                           opt.jobs, opt.cancel);
  else if (trials > 1)  // interrupted above: no trial runs, no grasp has all its trials
    add_perturbed_trials(doc, plan, hand, mesh, trials, opt.perturbation, opt.seed,
                         [&](int done, int total, const SimResult&) {
                           if (cb.grasp_line)
                             cb.grasp_line("grasp " + std::to_string(done - 1) + ": " +
                                           trials_line(doc.trial_outcomes[static_cast<size_t>(
                                               done - 1)]));
                           if (cb.progress) cb.progress("trials of grasps", done, total);
                         },
                         opt.jobs, opt.cancel, watch);
  doc.grasps_asked = asked;
  doc.plan_path = canonical(opt.plan);
  doc.object_path = opt.object.empty() ? plan.object_path : canonical(opt.object);
  if (!opt.trace_path.empty()) {
    for (const int k : doc.grasp_indices) trace << trace_rows[static_cast<size_t>(k)];
    write_file_atomically(opt.trace_path, trace.str());
  }
  if (video) {
    // grasp_K.webp (as planned), grasp_K_trial_T.webp (nudged trials); trial samples are kept
    // by the grasp's index among the results before trials (a cancelled run drops some).
    Renderer animator;
    const auto write = [&](const std::string& name, const std::vector<PhaseSnapshot>& s,
                           const SimResult& r, const std::string& title) {
      if (s.empty()) return;
      write_file_atomically((std::filesystem::path(opt.video_dir) / (name + ".webp")).string(),
                            physics_animation(animator, hand, object, s, r, params, title,
                                              opt.video));
    };
    for (size_t i = 0; i < doc.results.size() && !opt.cancel.cancelled(); ++i) {
      const int k = doc.grasp_indices[i];
      const std::string name = "grasp_" + std::to_string(k);
      const std::string title = plan.object_name + " · " + hand.name + " · grasp " +
                                std::to_string(k);
      write(name, samples[static_cast<size_t>(k)], doc.results[i], title);
      for (int t = 1; t < trials && !trial_samples.empty(); ++t) {
        const size_t before = static_cast<size_t>(
            std::find(trial_index.begin(), trial_index.end(), k) - trial_index.begin());
        if (before >= trial_samples.size()) continue;
        write(name + "_trial_" + std::to_string(t), trial_samples[before][size_t(t)],
              trial_results[before][size_t(t)], title + " · trial " + std::to_string(t));
      }
      if (cb.progress) cb.progress("animations", static_cast<int>(i) + 1,
                                   static_cast<int>(doc.results.size()));
    }
  }
  write_sim_file(opt.out, doc, hand);
  return doc;
}

}  // namespace cordgrasp
