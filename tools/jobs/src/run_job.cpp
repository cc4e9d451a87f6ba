#include "cordgrasp/jobs/run_job.h"

#include <chrono>
#include <filesystem>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <utility>

#include "cordgrasp/core/assets.h"
#include "cordgrasp/core/atomic_file.h"
#include "cordgrasp/core/error.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/object_meshes.h"
#include "cordgrasp/jobs/hand_scene.h"
#include "cordgrasp/jobs/physics_animation.h"
#include "cordgrasp/jobs/physics_settings.h"
#include "cordgrasp/jobs/plan_json.h"
#include "cordgrasp/jobs/report_viewer.h"
#include "cordgrasp/jobs/run_report_html.h"
#include "cordgrasp/jobs/text_format.h"
#include "cordgrasp/jobs/validate_plan.h"
#include "cordgrasp/jobs/validated_plan_job.h"
#include "cordgrasp/render/contact_sheet.h"
#include "cordgrasp/render/png_io.h"
#include "cordgrasp/render/renderer.h"

namespace cordgrasp {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// Phases whose end states the physics picture shows.
bool pictured_phase(const std::string& phase) {
  return phase == "close" || phase == "lift" || phase == "shake";
}

/// A run's inputs, checked and loaded before any long stage, and its output files.
struct RunInputs {
  std::string object_path;
  std::shared_ptr<const Mesh> mesh;
  HandModel hand;
  PictureOptions picture;
  bool physics = false;  ///< tests other than "none"
  SimTests tests;
  std::string plan_path, report_path, html_path, sim_path;
};

/// Each grasp's physics samples (every 1 / video.frame_rate_hz and at phase ends) for the
/// pictures, the animations and the trace, with the physics settings they were taken with.
struct GraspSamples {
  std::vector<std::vector<PhaseSnapshot>> grasps;
  SimParams params;
};

RunInputs load_run_inputs(const RunParams& opt) {
  RunInputs in;
  in.physics = opt.tests != "none";
  in.tests = in.physics ? sim_tests_from_string(opt.tests) : SimTests{};
  // Check every input before the long stages: a bad size fails now, not after planning.
  in.picture = opt.picture;
  if (in.picture.view.empty()) in.picture.view = "iso";
  parse_image_size(in.picture.size);
  if (fs::exists(opt.out_dir) && !fs::is_directory(opt.out_dir))
    throw InputError("run: --out-dir '" + opt.out_dir + "' exists and is not a directory");
  in.object_path = resolve_object_path(opt.object);
  in.mesh = std::make_shared<const Mesh>(load_job_mesh(opt.job, in.object_path));
  in.hand = load_hand(opt.hand, opt.hand_load);
  fs::create_directories(opt.out_dir);  // only once the inputs have loaded
  in.plan_path = (fs::path(opt.out_dir) / "plan.json").string();
  in.report_path = (fs::path(opt.out_dir) / "report.md").string();
  in.html_path = (fs::path(opt.out_dir) / "report.html").string();
  in.sim_path = (fs::path(opt.out_dir) / "sim.json").string();
  return in;
}

/// 1. Plan (validated: only grasps that hold in physics) and write plan.json.
void plan_stage(const RunParams& opt, const RunInputs& in, const RunProgress& progress,
                RunReport* report) {
  const bool validated = in.physics && opt.validate;
  ValidationParams validation = opt.validation;
  validation.tests = opt.tests;
  validation.protocol = opt.protocol;
  progress("plan: " + std::string(to_string(opt.job.planner)) + " planner, hand " +
           in.hand.name + ", object " + in.mesh->name + " (" +
           std::to_string(in.mesh->triangles.size()) + " triangles), " +
           std::to_string(opt.job.plan.grasps) +
           (validated ? " grasps that hold in physics within a budget of " +
                            fixed(validation.budget_s, 0) + " s"
                      : " grasps within " + fixed(opt.job.plan.time_limit_s, 0) + " s"));
  const auto t = Clock::now();
  report->plan = validated ? validated_plan_job(opt.job, validation, *in.mesh, in.object_path,
                                                in.hand, opt.jobs, progress, opt.cancel)
                           : plan_job(opt.job, *in.mesh, in.object_path, in.hand, opt.cancel,
                                      opt.jobs);
  report->plan_wall_s = seconds_since(t);
  write_plan_file(in.plan_path, report->plan, in.hand);
}

/// Writes report.md and report.html.
void write_reports(const RunInputs& in, const RunReport& report, const ReportViewer& viewer) {
  write_file_atomically(in.report_path, run_report_markdown(report));
  write_file_atomically(in.html_path, run_report_html(report, viewer));
}

/// Throws NoGraspFound (after writing report.md and report.html) when the plan has no grasp.
void require_grasps(const RunInputs& in, const RunReport& report) {
  const PlanDocument& plan = report.plan;
  if (!plan.grasps.empty()) return;
  write_reports(in, report, {});
  throw NoGraspFound(no_accepted_grasp_message("run", plan, *in.mesh) + ". Wrote " +
                     in.plan_path + " and " + in.report_path);
}

/// 2. Physics of the plan as written (`written`: plan.json read back, poses as quaternions,
/// so that `cordgrasp validate --plan` reproduces these outcomes exactly); keeps the samples
/// for the pictures in `samples`.
SimDocument physics_stage(const RunParams& opt, const RunInputs& in, const PlanDocument& written,
                          const RunProgress& progress, GraspSamples* samples, RunReport* report) {
  PhysicsChoice choice;
  choice.protocol = opt.protocol;
  choice.overrides = opt.validation.physics;
  choice.file = opt.validation.physics_file;
  SimParams params = physics_settings(plan_contact_model(written), choice);
  if (opt.validate) params.squeeze_shift_limit_m = opt.validation.squeeze_shift_limit_m;
  if (opt.render) params.trace_interval_s = 1.0 / opt.video.frame_rate_hz;  // no effect on physics
  samples->params = params;
  const auto t = Clock::now();
  const auto hooks = [&](int k) -> PhaseHook {
    if (!opt.render) return {};
    return [samples, k](const PhaseSnapshot& s) {
      samples->grasps[static_cast<size_t>(k)].push_back(s);
    };
  };
  SimDocument sim = validate_plan(
      written, in.hand, *in.mesh, params, in.tests, -1,
      [&](int done, int total, const SimResult& r) {
        progress("physics: grasp " + std::to_string(done) + "/" + std::to_string(total) + " " +
                 sim_result_line(r));
      },
      hooks, opt.jobs, opt.cancel);
  sim.plan_path = fs::absolute(in.plan_path).lexically_normal().string();
  report->sim_wall_s = seconds_since(t);
  return sim;
}

/// Draws of each grasp's P(held) for sim.json and the report: the acceptance's model with
/// its validation.max_draws, else the realistic model in a preview of hold_preview_draws;
/// 0 draws: none.
int hold_draws(const RunParams& opt) {
  return is_none(opt.validation.uncertainty) ? opt.hold_preview_draws : opt.validation.max_draws;
}

/// 2b. P(held) of every grasp of `sim` (a copy: it may run beside the pictures), with each
/// grasp's own draws (by its index in the plan: not those that accepted it), so the report's
/// interval is an independent check. Returns `sim` with hold_probabilities (trimmed and
/// marked interrupted when cancelled) and the wall time it took.
std::pair<SimDocument, double> hold_probability_stage(const RunParams& opt, const RunInputs& in,
                                                      const PlanDocument& written, SimDocument sim,
                                                      int threads, const RunProgress& progress) {
  const auto t = Clock::now();
  const bool accepted_by_model = !is_none(opt.validation.uncertainty);
  const HoldProbabilityParams test = hold_test_params(opt.validation.min_hold_probability,
                                                      hold_draws(opt), opt.validation.trial_seed);
  add_hold_probabilities(
      sim, written, in.hand, *in.mesh,
      accepted_by_model ? opt.validation.uncertainty : UncertaintyParams{}, test,
      [&](int done, int total, const SimResult&) {
        progress("physics: P(held) of grasp " + std::to_string(done) + "/" + std::to_string(total) +
                 " " +
                 hold_probability_line(sim.hold_probabilities[static_cast<size_t>(done - 1)]));
      },
      threads, opt.cancel);
  return {std::move(sim), seconds_since(t)};
}

/// Pictures of grasp k's physics frames as one strip.
Image physics_strip(Renderer& renderer, const RunInputs& in, const HandMeshes& meshes,
                    const RenderParams& params, int k, const SimResult& r,
                    const std::vector<SnapshotFrame>& frames) {
  Scene empty;
  RenderParams snap = render_params(in.picture, empty);
  snap.width_px = params.width_px / 2;
  snap.height_px = params.height_px / 2;
  // Each panel framed on the object and the fingers at that moment.
  std::vector<std::string> captions;
  std::vector<Image> panels;
  for (const SnapshotFrame& frame : frames) {
    const PhaseResult* p = r.phase(frame.name);
    captions.push_back("after " + frame.name +
                       (p ? std::string(" · ") + to_string(p->outcome) : std::string()));
    Scene scene;
    add_object(scene, in.mesh, frame.X_WO);
    add_hand(scene, meshes, frame.X_WL);
    scene.ground = Ground::kShadow;
    RenderParams panel = snap;
    panel.camera = frame_on_grasp(in.hand, meshes, in.mesh, frame.X_WO, frame.X_WL, snap, false);
    panels.push_back(renderer.render(scene, panel));
  }
  ContactSheetParams strip;
  strip.columns = static_cast<int>(frames.size());
  strip.title = in.mesh->name + " · " + in.hand.name + " · grasp " + std::to_string(k) +
                " in Bullet: " + to_string(r.outcome);
  return compose_contact_sheet(panels, captions, strip);
}

/// What render_stage drew: the grasps pictured and the contact sheet's tiles and captions.
struct RenderedGrasps {
  int pictured = 0;
  std::vector<Image> tiles;
  std::vector<std::string> captions;
};

/// 3. Pictures: each planned grasp (cords, contacts), its physics frames, a contact sheet, and
/// its 3D model for report.html's viewer (none, saying why, when three.js is missing).
/// Returns the grasps pictured (fewer than planned when cancelled) and the contact sheet's tiles.
RenderedGrasps render_stage(const RunParams& opt, const RunInputs& in, const RunProgress& progress,
                            const GraspSamples& samples, RunReport* report, ReportViewer* viewer) {
  const auto t = Clock::now();
  try {
    write_viewer_scripts(opt.out_dir, opt.viewer);
    viewer->scripts_dir = kViewerDir;
  } catch (const InputError& e) {
    viewer->unavailable = e.what();
    progress("render: no 3D view in report.html: " + viewer->unavailable);
  }
  const PlanDocument& plan = report->plan;
  const int n = static_cast<int>(plan.grasps.size());
  Renderer renderer;
  const HandMeshes meshes = make_hand_meshes(in.hand);
  OverlayStyle overlay;
  overlay.friction_coefficient = opt.job.plan.quality.contact.mu;
  RenderedGrasps out;
  for (int k = 0; k < n && !opt.cancel.cancelled(); ++k) {
    const Grasp& g = plan.grasps[static_cast<size_t>(k)];
    GraspPictures pics;
    Scene scene =
        grasp_scene(in.hand, meshes, in.mesh, g, g.region ? &*g.region : nullptr, overlay);
    const std::string quality =
        "α = " + fixed(g.alpha_rad, 3) + " rad · ε = " + fixed(g.epsilon, 4);
    scene.caption = in.mesh->name + " · " + in.hand.name + " · grasp " + std::to_string(k) +
                    " · " + quality;
    const RenderParams params = render_params(in.picture, scene, g.X_OG.linear().col(2));
    pics.planned = "grasp_" + std::to_string(k) + ".png";
    write_png((fs::path(opt.out_dir) / pics.planned).string(), renderer.render(scene, params));
    if (n > 1) {
      scene.caption.clear();
      out.tiles.push_back(renderer.render(scene, params));
      out.captions.push_back("#" + std::to_string(k) + " · " + quality);
    }
    const std::vector<PhaseSnapshot>& s =
        samples.grasps.empty() ? std::vector<PhaseSnapshot>{} : samples.grasps[size_t(k)];
    std::vector<SnapshotFrame> f;
    for (const PhaseSnapshot& x : s) {
      if (x.phase_end && pictured_phase(x.phase)) f.push_back({x.X_WL, x.X_WO, "", x.phase});
      pics.trace.push_back({x.phase, x.phase_end, x.sim_time_s, x.object_shift_m,
                            x.object_turn_rad, x.contact_count});
    }
    if (!f.empty()) {
      const SimResult& result = report->sim->results[static_cast<size_t>(k)];
      pics.snapshots.push_back("grasp_" + std::to_string(k) + "_physics.png");
      write_png((fs::path(opt.out_dir) / pics.snapshots.back()).string(),
                physics_strip(renderer, in, meshes, params, k, result, f));
      pics.animation = "grasp_" + std::to_string(k) + ".webp";
      write_file_atomically((fs::path(opt.out_dir) / pics.animation).string(),
                            physics_animation(renderer, in.hand, in.mesh, s, result,
                                              samples.params,
                                              in.mesh->name + " · " + in.hand.name +
                                                  " · grasp " + std::to_string(k),
                                              opt.video));
    }
    report->pictures.push_back(pics);
    viewer->models.emplace_back();
    if (!viewer->scripts_dir.empty()) {
      viewer->models.back() = "grasp_" + std::to_string(k);
      write_grasp_model_script(opt.out_dir, viewer->models.back(), in.hand, g, *in.mesh);
    }
    out.pictured = k + 1;
    progress("render: grasp " + std::to_string(k + 1) + "/" + std::to_string(n));
  }
  report->render_wall_s = seconds_since(t);
  return out;
}

/// The contact sheet of all grasps (grasps.png), written only once every grasp is pictured.
void write_contact_sheet(const RunParams& opt, const RunInputs& in, const RenderedGrasps& rendered,
                         RunReport* report) {
  if (rendered.tiles.empty()) return;
  const auto t = Clock::now();
  ContactSheetParams sheet;
  sheet.title = in.mesh->name + " · " + in.hand.name + " · " + to_string(opt.job.planner) +
                " planner · " + std::to_string(rendered.pictured) + " grasps";
  report->sheet = "grasps.png";
  write_png((fs::path(opt.out_dir) / report->sheet).string(),
            compose_contact_sheet(rendered.tiles, rendered.captions, sheet));
  report->render_wall_s += seconds_since(t);
}

}  // namespace

RunOutcome run_job(const RunParams& opt, const RunProgress& say) {
  const RunProgress progress = [&](const std::string& text) { if (say) say(text); };
  const RunInputs in = load_run_inputs(opt);
  RunOutcome out;
  RunReport& report = out.report;
  ReportViewer viewer;
  // Writes report.md and report.html (stopped early: saying where) and returns what the run did.
  const auto finish = [&](const std::string& reason, const std::string& at) {
    report.interrupted = reason;
    report.interrupted_at = at;
    write_reports(in, report, viewer);
    if (report.sim)
      for (const SimResult& r : report.sim->results) out.held += r.held();
    out.report_path = in.report_path;
    out.html_path = in.html_path;
    return std::move(out);
  };

  plan_stage(opt, in, progress, &report);
  out.plan_path = in.plan_path;
  const PlanDocument& plan = report.plan;
  const int n = static_cast<int>(plan.grasps.size());
  if (!plan.interrupted.empty())
    return finish(plan.interrupted, "planning, after " + std::to_string(n) + " of " +
                                        std::to_string(plan.params.grasps) + " grasps");
  progress("plan: " + (plan.validation
                           ? validation_stats_line(plan.validation->stats, plan.params.grasps)
                           : std::to_string(n) + " force-closure grasp(s), " +
                                 std::to_string(plan.stats.attempts) + " attempts"));
  require_grasps(in, report);

  GraspSamples samples;
  samples.grasps.resize(static_cast<size_t>(n));
  std::optional<PlanDocument> written;
  if (in.physics) {
    written = plan_from_json(read_plan_json(in.plan_path), in.hand, in.plan_path);
    report.sim = physics_stage(opt, in, *written, progress, &samples, &report);
    out.sim_path = in.sim_path;
    if (!report.sim->interrupted.empty()) {
      write_sim_file(in.sim_path, *report.sim, in.hand);
      return finish(report.sim->interrupted, "physics, after " +
                                                 std::to_string(report.sim->results.size()) +
                                                 " of " + std::to_string(n) + " grasps");
    }
  }
  // With more than one thread, P(held)'s draws (on `jobs` threads) run while the renderer
  // (one thread) draws the pictures, else after them; the results do not depend on which.
  const bool draws = in.physics && hold_draws(opt) > 0;
  const bool beside = draws && opt.render && opt.jobs > 1;
  std::mutex saying;
  const RunProgress said = [&](const std::string& text) {
    const std::lock_guard<std::mutex> lock(saying);
    progress(text);
  };
  std::future<std::pair<SimDocument, double>> held;
  if (draws)
    held = std::async(beside ? std::launch::async : std::launch::deferred,
                      [&, sim = *report.sim, threads = opt.jobs]() mutable {
                        return hold_probability_stage(opt, in, *written, std::move(sim), threads,
                                                      said);
                      });
  RenderedGrasps rendered;
  if (opt.render) rendered = render_stage(opt, in, said, samples, &report, &viewer);
  if (draws) {
    auto [sim, wall_s] = held.get();
    report.sim = std::move(sim);  // trimmed to the grasps whose draws finished
    report.sim_wall_s += wall_s;
  }
  if (in.physics) {
    write_sim_file(in.sim_path, *report.sim, in.hand);
    if (!report.sim->interrupted.empty())
      return finish(report.sim->interrupted,
                    "physics, after " + std::to_string(report.sim->results.size()) + " of " +
                        std::to_string(n) + " grasps");
  }
  if (opt.render) {
    if (rendered.pictured < n)
      return finish(opt.cancel.reason(), "rendering, after " + std::to_string(rendered.pictured) +
                                             " of " + std::to_string(n) + " grasps");
    write_contact_sheet(opt, in, rendered, &report);
  }
  return finish("", "");
}

}  // namespace cordgrasp
