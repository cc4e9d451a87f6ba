#pragma once
// `cordgrasp validate` as a job: read plan.json, check its grasps in physics (with trials,
// snapshots and a trace), write sim.json.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "cordgrasp/core/cancel_token.h"
#include "cordgrasp/core/grasp_perturbation.h"
#include "cordgrasp/core/hand_description.h"
#include "cordgrasp/jobs/physics_animation.h"
#include "cordgrasp/jobs/validate_plan.h"
#include "cordgrasp/sim/sim_params.h"

namespace cordgrasp {

/// Inputs and settings of validate_job(); unset optionals keep the SimParams defaults (μ and
/// the soft-finger radius: the plan's).
struct ValidateJobParams {
  std::string plan;
  std::string hand;
  HandLoadOptions hand_load;  ///< package:// directories of the hand's URDF
  std::string object;
  std::string units;
  std::optional<double> scale;  ///< object scale (default: the plan's)
  std::string tests = "lift,shake,gravity6";
  Protocol protocol = SimParams{}.protocol;  ///< preset applied before the options below
  std::optional<double> mu;
  /// Mass, density, squeeze weight; unset: those the plan was validated with (its
  /// validation.parameters.physics, sim_overrides_or), else SimParams'.
  SimOverrides physics;
  /// Physics settings file merged over the preset and the above (merge_physics_file): every
  /// other SimParams field is set there. Empty: none.
  std::string physics_file;
  std::string cache_dir;  ///< SimParams::decomposition_cache_dir, unless the file sets it
  int grasps = -1;
  /// Simulations per grasp: as planned, then nudged (perturbation); with an uncertainty model,
  /// the most draws of the sequential P(held) test after the as-planned one. 0: 1 without a
  /// model; with one, the plan's validation.max_draws when the model is the plan's, else
  /// HoldProbabilityParams' max_draws.
  int trials = 0;
  /// "none" (trials are nudges), "realistic" or an uncertainty settings file
  /// (uncertainty_settings): each grasp's P(held) under uncertainty, after its as-planned run.
  /// Empty: the model the plan's grasps were accepted under (plan --validate --uncertainty),
  /// else none.
  std::string uncertainty;
  /// Acceptance threshold of the P(held) test (HoldProbabilityParams) [-]. 0: the plan's
  /// validation.min_hold_probability when the model is the plan's, else HoldProbabilityParams'.
  double min_hold_probability = 0.0;
  int jobs = 1;  ///< threads (one physics world each); results do not depend on it
  PerturbationParams perturbation;
  std::uint64_t seed = 1;  ///< seed of the nudges or the uncertain draws
  std::string snapshots_dir;
  /// Existing folder: one animated WebP per grasp, grasp_K.webp, and per nudged trial,
  /// grasp_K_trial_T.webp, of its phases.
  std::string video_dir;
  VideoParams video;  ///< size and rate of the animations
  std::string trace_path;  ///< every SimParams::trace_interval_s (0: kDefaultTraceInterval_s)
  std::string out;
  /// Stop request: no new grasp or trial starts once it is set (those in flight finish); the
  /// grasps whose every trial finished are written, sim.json marked incomplete.
  CancelToken cancel;
};

/// Called with one line per validated grasp ("grasp 0: held (...)"), and with
/// (done, total) for progress.
struct ValidateJobCallbacks {
  std::function<void(const std::string&)> grasp_line;
  std::function<void(const std::string& stage, int done, int total)> progress;
};

/// Trace interval of --trace when the settings set none [s].
constexpr double kDefaultTraceInterval_s = 0.01;

/// The physics settings validate_job(p) simulates with (physics_settings): p.protocol's
/// preset, the plan's μ and soft-finger radius (or p.mu), the mass, density and squeeze weight
/// (p.physics, else the plan's validation record), the cache folder, then p.physics_file
/// (else the validated plan's settings file).
/// @throws InputError naming the file for an unreadable plan or settings file.
SimParams validate_job_physics(const ValidateJobParams& p);

/// Validates the plan p.plan as the options say and writes sim.json to p.out (and the trace
/// and snapshots when asked). Output folders are checked before any simulation. When
/// p.cancel stopped it, the document's `interrupted` is set and the files hold what finished.
/// @throws InputError naming the file or option.
SimDocument validate_job(const ValidateJobParams& p, const ValidateJobCallbacks& callbacks = {});

}  // namespace cordgrasp
