#pragma once
// Validating a plan in physics: every grasp (or the first K) through the requested tests, with
// repeated perturbed trials; the one path that `validate`, `run` and `bench` share.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cordgrasp/core/cancel_token.h"
#include "cordgrasp/core/grasp_perturbation.h"
#include "cordgrasp/core/hand_model.h"
#include "cordgrasp/core/mesh.h"
#include "cordgrasp/jobs/plan_json.h"
#include "cordgrasp/sim/hold_probability.h"
#include "cordgrasp/sim/validate_grasp.h"

namespace cordgrasp {

/// Result of validating (some of) the grasps of a plan.
struct SimDocument {
  std::string plan_path;
  std::string hand_name;
  std::string hand_path;
  std::string object_path;
  std::string object_name;
  std::string object_units = "m";
  double object_scale = 1.0;
  int object_triangles = 0;
  std::optional<std::uint64_t> plan_seed;  ///< the plan's seed (the simulation draws none)
  SimParams params;
  SimTests tests;
  std::vector<int> grasp_indices;  ///< index of each result's grasp in the plan
  std::vector<SimResult> results;
  std::vector<Grasp> grasps;       ///< the validated grasps (for ε, force closure)
  double wall_time_s = 0.0;
  /// Repeated trials (add_perturbed_trials): per grasp, the outcome of every trial; trial 0 is
  /// results[k]. Empty when each grasp was simulated once.
  std::vector<std::vector<Outcome>> trial_outcomes;
  /// How far the object moved in the hand while it closed, per grasp and trial as
  /// trial_outcomes: {shift [m], turn [rad]} of the close phase (NaN when close did not run).
  std::vector<std::vector<std::pair<double, double>>> trial_close_motion;
  PerturbationParams trial_perturbation;
  std::uint64_t trial_seed = 1;
  int trials = 1;  ///< simulations asked for per grasp (add_perturbed_trials)
  /// P(held) under uncertainty (add_hold_probabilities), per grasp as results; empty when
  /// not asked for.
  std::vector<HoldProbability> hold_probabilities;
  UncertaintyParams uncertainty = uncertainty_none();  ///< the model of hold_probabilities
  HoldProbabilityParams hold_test;  ///< its sequential test
  /// The signal that stopped the validation early ("SIGINT"), "" when it ran to its end; the
  /// document then holds only the grasps whose every simulation finished.
  std::string interrupted;
  int grasps_asked = 0;  ///< grasps the validation was asked for (results: fewer if interrupted)
};

/// Called after each grasp: (done, total, result).
using ValidateProgress = std::function<void(int, int, const SimResult&)>;

/// Gives the phase hook (may be empty) for the grasp with this index in the plan.
using GraspPhaseHooks = std::function<PhaseHook(int grasp_index)>;

/// Validates the first `max_grasps` grasps of `plan` (all when < 0) on `mesh` with `hand`;
/// `hooks` (optional) sees the world at every phase end of each grasp (snapshots). `jobs`
/// threads simulate grasps at once, each in its own world: the document does not depend on it;
/// `progress` is called in grasp order, one call at a time, and a hook of grasp k runs on the
/// thread simulating k (so it must only touch grasp k's state). Once `cancel` is set no further
/// grasp starts (those in flight finish); the document keeps the finished ones, with
/// doc.interrupted set when some were not simulated.
SimDocument validate_plan(const PlanDocument& plan, const HandModel& hand, const Mesh& mesh,
                          const SimParams& params, const SimTests& tests, int max_grasps = -1,
                          const ValidateProgress& progress = {},
                          const GraspPhaseHooks& hooks = {}, int jobs = 1,
                          const CancelToken& cancel = {});

/// What add_perturbed_trials' `watch`, if set, sees: each trial's physics (its hook, e.g. for an animation) and result.
struct TrialWatch {
  std::function<PhaseHook(int k, int trial)> hook;  ///< phase hook of trial `trial` of grasp k
  std::function<void(int k, int trial, const SimResult&)> done;  ///< on the trial's thread
};

/// Held / not-held of a marginal grasp is chaotic (docs/physics.md): validates every grasp of
/// `doc` `trials` − 1 more times with the hand moved and turned slightly (perturbed_grasp,
/// seed trial_seed + 1000·k + t for trial t of grasp k) and records all outcomes in
/// doc.trial_outcomes; `progress` is called after each grasp's trials, in grasp order. `jobs`
/// threads run the trials (results independent of it); `watch` sees each trial. Once `cancel` is set no further trial
/// starts; grasps whose trials did not all run are removed from `doc` and doc.interrupted set.
/// @throws std::invalid_argument when trials is not in [1, 1000].
void add_perturbed_trials(SimDocument& doc, const PlanDocument& plan, const HandModel& hand,
                          const Mesh& mesh, int trials, const PerturbationParams& perturbation,
                          std::uint64_t seed, const ValidateProgress& progress = {},
                          int jobs = 1, const CancelToken& cancel = {},
                          const TrialWatch& watch = {});

/// P(held) of every grasp of `doc` under `uncertainty` (estimate_hold_probability with
/// doc.params and doc.tests, each grasp by its index in the plan), into
/// doc.hold_probabilities; the as-planned results stay. `jobs` threads estimate grasps at once
/// (each grasp's draws run in order; results independent of `jobs`); `progress` is called in
/// grasp order. Once `cancel` is set no further draw starts; grasps whose test did not finish
/// are removed from `doc` and doc.interrupted set.
/// @throws std::invalid_argument for bad parameters.
void add_hold_probabilities(SimDocument& doc, const PlanDocument& plan, const HandModel& hand,
                            const Mesh& mesh, const UncertaintyParams& uncertainty,
                            const HoldProbabilityParams& test,
                            const ValidateProgress& progress = {}, int jobs = 1,
                            const CancelToken& cancel = {});

/// The closing lines of a validation: "held 2 / 3 (tests lift,shake, mu 0.5) -> OUT", the
/// failures_line and, with trials, "held in k / N trials of all grasps" (with P(held):
/// "P(held) above 0.8: k of N grasps, median draws D"); each ends in '\n'.
std::string validation_summary(const SimDocument& doc, const std::string& tests,
                               const std::string& out_path);

/// Trials of a grasp that held: "held in 3 / 5 trials".
std::string trials_line(const std::vector<Outcome>& outcomes);

/// "held (lift held, shake held, gravity6 held) mass 0.12 kg, 0.41 s"
std::string sim_result_line(const SimResult& result);

/// Grasps that did not hold, by the first phase that failed (settle, close, lift, shake,
/// gravity6, in that order), and grasps whose preshape hand overlapped the object.
struct FailureCounts {
  std::vector<std::pair<std::string, int>> by_phase;
  int preshape_overlaps = 0;
  int not_pressing = 0;  ///< lost after the close with no finger pressing (lost_without_pressing)
};
FailureCounts count_failures(const std::vector<SimResult>& results);

/// "not held by phase: settle 0, close 2, lift 1, shake 0, gravity6 0; preshape overlaps 1",
/// then "; no finger pressing after the close 1" when any.
std::string failures_line(const std::vector<SimResult>& results);

}  // namespace cordgrasp
