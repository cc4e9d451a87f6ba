#include "cordgrasp/jobs/run_job.h"

#include <chrono>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "cordgrasp/core/assets.h"
#include "cordgrasp/core/atomic_file.h"
#include "cordgrasp/core/error.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/object_meshes.h"
#include "cordgrasp/jobs/hand_scene.h"
#include "cordgrasp/jobs/plan_json.h"
#include "cordgrasp/jobs/physics_settings.h"
#include "cordgrasp/jobs/plan_validated_grasps.h"
#include "cordgrasp/jobs/text_format.h"
#include "cordgrasp/jobs/validate_plan.h"
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

}  // namespace

RunOutcome run_job(const RunParams& opt, const RunProgress& say) {
  const auto progress = [&](const std::string& text) { if (say) say(text); };
  RunOutcome out;
  const bool physics = opt.tests != "none";
  const SimTests tests = physics ? sim_tests_from_string(opt.tests) : SimTests{};
  // Check every input before the long stages: a bad size fails now, not after planning.
  PictureOptions picture = opt.picture;
  if (picture.view.empty()) picture.view = "iso";
  parse_image_size(picture.size);
  if (fs::exists(opt.out_dir) && !fs::is_directory(opt.out_dir))
    throw InputError("run: --out-dir '" + opt.out_dir + "' exists and is not a directory");

  const std::string object_path = resolve_object_path(opt.object);
  const auto mesh = std::make_shared<const Mesh>(load_job_mesh(opt.job, object_path));
  const HandModel hand = load_hand(opt.hand, opt.hand_load);
  fs::create_directories(opt.out_dir);  // only once the inputs have loaded

  // 1. Plan (validated: only grasps that hold in physics).
  const bool validated = physics && opt.validate;
  ValidationParams validation = opt.validation;
  validation.tests = opt.tests;
  validation.protocol = opt.protocol;
  progress("plan: " + std::string(to_string(opt.job.planner)) + " planner, hand " + hand.name + ", object " +
               mesh->name + " (" + std::to_string(mesh->triangles.size()) + " triangles), " +
               std::to_string(opt.job.plan.grasps) +
               (validated ? " grasps that hold in physics within a budget of " +
                                fixed(validation.budget_s, 0) + " s"
                          : " grasps within " + fixed(opt.job.plan.time_limit_s, 0) + " s"));
  auto t = Clock::now();
  RunReport& report = out.report;
  if (validated)
    report.plan = plan_validated_grasps(opt.job, validation, *mesh, object_path, hand,
                                        opt.jobs, progress, opt.cancel);
  else
    report.plan = plan_job(opt.job, *mesh, object_path, hand, opt.cancel);
  report.plan_wall_s = seconds_since(t);
  const PlanDocument& plan = report.plan;
  const std::string plan_path = (fs::path(opt.out_dir) / "plan.json").string();
  const std::string report_path = (fs::path(opt.out_dir) / "report.md").string();
  write_plan_file(plan_path, plan, hand);
  out.plan_path = plan_path;
  // Stopped early: report.md says where; the files written hold what finished.
  const auto stop = [&](const std::string& reason, const std::string& at) {
    report.interrupted = reason;
    report.interrupted_at = at;
    write_file_atomically(report_path, run_report_markdown(report));
    for (const SimResult& r : out.sim.results) out.held += r.held();
    out.report_path = report_path;
    report.sim = nullptr;  // points into `out`, which moves on return
    return std::move(out);
  };
  if (!plan.interrupted.empty())
    return stop(plan.interrupted, "planning, after " + std::to_string(plan.grasps.size()) +
                                      " of " + std::to_string(plan.params.grasps) + " grasps");
  // Physics sees the plan as written (poses as quaternions), so `cordgrasp validate --plan
  // plan.json` later reproduces these outcomes exactly.
  const PlanDocument written = plan_from_json(read_plan_json(plan_path), hand, plan_path);
  const int n = static_cast<int>(plan.grasps.size());
  if (plan.validation)
    progress("plan: " + validation_stats_line(plan.validation->stats, plan.params.grasps));
  else
    progress("plan: " + std::to_string(n) + " force-closure grasp(s), " +
             std::to_string(plan.stats.attempts) + " attempts");
  if (n == 0 && plan.validation && plan.validation->stats.force_closure > 0) {
    write_file_atomically(report_path, run_report_markdown(report));
    throw NoGraspFound("run: no grasp of " + mesh->name + " with " + hand.name +
                             " held in physics (" +
                             validation_stats_line(plan.validation->stats, plan.params.grasps) +
                             "); try a larger --budget, another --seed or --planner. Wrote " +
                             plan_path + " and " + report_path);
  }
  if (n == 0) {
    write_file_atomically(report_path, run_report_markdown(report));
    throw NoGraspFound(no_grasp_message("run", plan, *mesh) + ". Wrote " + plan_path + " and " +
                       report_path);
  }

  // 2. Physics, keeping the world at the ends of close, lift and shake for the pictures.
  SimDocument& sim = out.sim;
  std::vector<std::vector<SnapshotFrame>> frames(static_cast<size_t>(n));
  if (physics) {
    PhysicsChoice choice;
    choice.protocol = opt.protocol;
    choice.overrides = opt.validation.physics;
    choice.file = opt.validation.physics_file;
    SimParams params = physics_settings(plan_contact_model(written), choice);
    if (validated) params.squeeze_shift_limit_m = validation.squeeze_shift_limit_m;
    t = Clock::now();
    const auto hooks = [&](int k) -> PhaseHook {
      if (!opt.render) return {};
      return [&frames, k](const PhaseSnapshot& s) {
        if (!s.phase_end || !pictured_phase(s.phase)) return;
        SnapshotFrame f;
        f.X_WL = s.X_WL;
        f.X_WO = s.X_WO;
        f.name = s.phase;
        frames[static_cast<size_t>(k)].push_back(std::move(f));
      };
    };
    sim = validate_plan(
        written, hand, *mesh, params, tests, -1,
        [&](int done, int total, const SimResult& r) {
          progress("physics: grasp " + std::to_string(done) + "/" + std::to_string(total) +
                       " " + sim_result_line(r));
        },
        hooks, opt.jobs, opt.cancel);
    sim.plan_path = fs::absolute(plan_path).lexically_normal().string();
    report.sim_wall_s = seconds_since(t);
    out.sim_path = (fs::path(opt.out_dir) / "sim.json").string();
    write_sim_file(out.sim_path, sim, hand);
    report.sim = &sim;
    if (!sim.interrupted.empty())
      return stop(sim.interrupted, "physics, after " + std::to_string(sim.results.size()) +
                                       " of " + std::to_string(n) + " grasps");
  }

  // 3. Pictures: each planned grasp (cords, contacts), its physics frames, a contact sheet.
  if (!!opt.render) {
    t = Clock::now();
    Renderer renderer;
    const HandMeshes meshes = make_hand_meshes(hand);
    OverlayStyle overlay;
    overlay.friction_coefficient = opt.job.plan.quality.contact.mu;
    std::vector<Image> tiles;
    std::vector<std::string> captions;
    for (int k = 0; k < n; ++k) {
      if (opt.cancel.cancelled()) {
        report.render_wall_s = seconds_since(t);
        return stop(opt.cancel.reason(), "rendering, after " + std::to_string(k) + " of " +
                                             std::to_string(n) + " grasps");
      }
      const Grasp& g = plan.grasps[static_cast<size_t>(k)];
      GraspPictures pics;
      Scene scene = grasp_scene(hand, meshes, mesh, g, g.region ? &*g.region : nullptr, overlay);
      const std::string quality =
          "α = " + fixed(g.alpha_rad, 3) + " rad · ε = " + fixed(g.epsilon, 4);
      scene.caption = mesh->name + " · " + hand.name + " · grasp " + std::to_string(k) + " · " +
                      quality;
      const RenderParams params = render_params(picture, scene, g.X_OG.linear().col(2));
      Image image = renderer.render(scene, params);
      pics.planned = "grasp_" + std::to_string(k) + ".png";
      write_png((fs::path(opt.out_dir) / pics.planned).string(), image);
      if (n > 1) {
        scene.caption.clear();
        tiles.push_back(renderer.render(scene, params));
        captions.push_back("#" + std::to_string(k) + " · " + quality);
      }
      auto& f = frames[static_cast<size_t>(k)];
      if (!f.empty()) {
        const SimResult& r = sim.results[static_cast<size_t>(k)];
        for (SnapshotFrame& frame : f) {
          const PhaseResult* p = r.phase(frame.name);
          frame.caption = "after " + frame.name + (p ? std::string(" · ") + to_string(p->outcome)
                                                     : std::string());
        }
        Scene empty;
        RenderParams snap = render_params(picture, empty);
        snap.width_px = params.width_px / 2;
        snap.height_px = params.height_px / 2;
        std::vector<std::string> snap_captions;
        for (const SnapshotFrame& frame : f) snap_captions.push_back(frame.caption);
        std::vector<SnapshotFrame> plain = f;
        for (SnapshotFrame& frame : plain) frame.caption.clear();
        ContactSheetParams strip;
        strip.columns = static_cast<int>(plain.size());
        strip.title = mesh->name + " · " + hand.name + " · grasp " + std::to_string(k) +
                      " in Bullet: " + to_string(r.outcome);
        const Image sheet = compose_contact_sheet(
            render_snapshots(renderer, hand, mesh, plain, snap), snap_captions, strip);
        pics.snapshots.push_back("grasp_" + std::to_string(k) + "_physics.png");
        write_png((fs::path(opt.out_dir) / pics.snapshots.back()).string(), sheet);
      }
      report.pictures.push_back(pics);
      progress("render: grasp " + std::to_string(k + 1) + "/" + std::to_string(n));
    }
    if (!tiles.empty()) {
      ContactSheetParams sheet;
      sheet.title = mesh->name + " · " + hand.name + " · " + to_string(opt.job.planner) + " planner · " +
                    std::to_string(n) + " grasps";
      report.sheet = "grasps.png";
      write_png((fs::path(opt.out_dir) / report.sheet).string(),
                compose_contact_sheet(tiles, captions, sheet));
    }
    report.render_wall_s = seconds_since(t);
  }

  write_file_atomically(report_path, run_report_markdown(report));
  for (const SimResult& r : sim.results) out.held += r.held();
  out.report_path = report_path;
  report.sim = nullptr;  // points into `out`, which moves on return
  return out;
}

}  // namespace cordgrasp
