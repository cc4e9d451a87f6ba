#pragma once
// The main job: plan → validate in physics → render → report.md and report.html, into one
// output folder.
#include <functional>
#include <optional>
#include <string>

#include "cordgrasp/core/cancel_token.h"
#include "cordgrasp/core/hand_description.h"
#include "cordgrasp/jobs/physics_animation.h"
#include "cordgrasp/jobs/plan_job.h"
#include "cordgrasp/jobs/render_options.h"
#include "cordgrasp/jobs/report_viewer.h"
#include "cordgrasp/jobs/run_report.h"
#include "cordgrasp/jobs/sim_json.h"
#include "cordgrasp/sim/grasp_validation.h"
#include "cordgrasp/sim/sim_params.h"

namespace cordgrasp {

/// Inputs and settings of run_job().
struct RunParams {
  std::string hand;            ///< hand description file or shipped hand name
  HandLoadOptions hand_load;   ///< package:// directories of the hand's URDF
  std::string object;          ///< object mesh file or shipped object name
  PlanJobParams job;           ///< planner settings (grasps = 3 on the command line)
  std::string tests = "lift,shake";  ///< physics tests (lift, shake, gravity6) or "none"
  Protocol protocol = SimParams{}.protocol;  ///< physics protocol preset
  int jobs = 1;                ///< physics threads (one world each); results independent of it
  /// Plan only grasps that hold (validated_plan_job, with `tests` and `protocol`); false:
  /// force-closure grasps as planned, validated afterwards. Ignored with tests "none".
  bool validate = true;
  /// Validated planning (its tests, protocol: from above); validation.physics (mass,
  /// density, squeeze weight) applies to the physics of the unvalidated plan too.
  ValidationParams validation;
  /// Draws of each grasp's P(held) under the realistic uncertainty model (docs/physics.md
  /// §3b) that sim.json and the report give when validation.uncertainty is none: a preview
  /// that flags fragile grasps, stopping sooner where the sequential test is decided (with a
  /// model, validation.max_draws draws of it instead). 0: no P(held).
  int hold_preview_draws = 5;
  PictureOptions picture;      ///< size of the pictures (view: iso)
  /// Write PNGs (planned grasps, physics frames, contact sheet), each grasp's physics
  /// animation (grasp_K.webp) and report.html's 3D models.
  bool render = true;
  VideoParams video;           ///< size and rate of the animations
  /// three.js files for report.html's 3D view (copied into out_dir/viewer when rendering);
  /// missing ones leave the report without 3D view, saying why.
  ViewerSources viewer = default_viewer_sources();
  std::string out_dir;         ///< output folder, created if missing
  /// Stop request, checked in the planner, before each grasp's physics and before each
  /// grasp's pictures; what finished is written, marked incomplete (RunReport::interrupted).
  CancelToken cancel;
};

/// What run_job() wrote.
struct RunOutcome {
  RunReport report;            ///< the plan, the physics (unset with tests "none"), pictures
  /// Files written ("" when not written); html_path: report.html (run_report_html).
  std::string plan_path, sim_path, report_path, html_path;
  int held = 0;                ///< grasps held through the tests (the planned pose, once)
};

/// One progress line ("plan: 3 force-closure grasp(s), 41 attempts").
using RunProgress = std::function<void(const std::string&)>;

/// Runs the whole job and writes plan.json, sim.json, report.md, report.html, PNGs and the 3D
/// models of report.html's viewer (report_viewer.h) to p.out_dir.
/// Physics sees the plan as written to plan.json, so `cordgrasp validate --plan` reproduces
/// its outcomes. @throws InputError for bad inputs (before any work), NoGraspFound when
/// no force-closure grasp was found, or with p.validate none held (plan.json, report.md and
/// report.html are written first). Stopped by p.cancel, it writes plan.json (and sim.json
/// when physics had begun) with what finished, marked incomplete, and the reports saying so,
/// and returns with report.interrupted set (NoGraspFound is not thrown then).
RunOutcome run_job(const RunParams& p, const RunProgress& progress = {});

}  // namespace cordgrasp
