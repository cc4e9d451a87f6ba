#pragma once
// sim.json: what `cordgrasp validate` writes (and `run` will embed), and the in-process
// validation of a whole plan that produces it.
//
// Layout (format_version 1), meters, radians, seconds, kilograms:
//   format: "cordgrasp-sim", format_version: 1, cordgrasp_version, backend (Bullet version)
//   inputs: {plan, hand: {name, path}, object: {path, name, units, triangles}, plan_seed}
//   parameters: {tests, mu, soft_finger_radius_m, time_step_s, solver_iterations, erp, ... every
//                SimParams field (sim_params_to_json)}
//   object: {shape, parts, mass_kg, volume_m3, closed, com_m, principal_inertia_kgm2,
//            decomposition_s}
//   grasps: [{index (in the plan), outcome, failed_phase (null when held), detail, epsilon,
//             force_closure, wall_time_s, trials (with --trials N > 1: {count, held,
//             outcomes: [trial 0 = the plan as written, then perturbed copies]}),
//             phases: [{name, outcome, detail, translation_m, rotation_rad, max_translation_m,
//                       in_contact, contact_count, max_contact_count, max_penetration_m,
//                       joint_efforts: {joint: N·m or N}, sim_time_s, wall_time_s, steps}]}]
//   summary: {grasps, held, outcomes: {held, slipped, dropped, unstable}, wall_time_s,
//             trials, held_trials (over every trial of every grasp)}
//   parameters also: trials, trial_offset_m, trial_turn_rad, trial_seed
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "cordgrasp/core/grasp_perturbation.h"
#include "cordgrasp/core/hand_model.h"
#include "cordgrasp/core/mesh.h"
#include "cordgrasp/sim/validate_grasp.h"
#include "plan_json.h"

namespace cordgrasp::cli {

/// Result of validating (some of) the grasps of a plan.
struct SimDocument {
  std::string plan_path;
  std::string hand_name;
  std::string hand_path;
  std::string object_path;
  std::string object_name;
  std::string object_units = "m";
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
  PerturbationParams trial_perturbation;
  std::uint64_t trial_seed = 1;
};

/// Every SimParams field as JSON (units in the names).
nlohmann::json sim_params_to_json(const SimParams& params);

/// One SimResult as JSON (joint names from `hand`).
nlohmann::json sim_result_to_json(const SimResult& result, const HandModel& hand);

/// JSON of a validation (layout above).
nlohmann::json sim_to_json(const SimDocument& doc, const HandModel& hand);

/// Writes sim_to_json() atomically. @throws InputError.
void write_sim_file(const std::string& path, const SimDocument& doc, const HandModel& hand);

/// Parses sim.json. @throws InputError naming the file (missing, not JSON, not a sim file).
nlohmann::json read_sim_json(const std::string& path);

/// Called after each grasp: (done, total, result).
using ValidateProgress = std::function<void(int, int, const SimResult&)>;

/// Gives the phase hook (may be empty) for the grasp with this index in the plan.
using GraspPhaseHooks = std::function<PhaseHook(int grasp_index)>;

/// Validates the first `max_grasps` grasps of `plan` (all when < 0) on `mesh` with `hand`;
/// `hooks` (optional) sees the world at every phase end of each grasp (snapshots).
SimDocument validate_plan(const PlanDocument& plan, const HandModel& hand, const Mesh& mesh,
                          const SimParams& params, const SimTests& tests, int max_grasps = -1,
                          const ValidateProgress& progress = {},
                          const GraspPhaseHooks& hooks = {});

/// Held / not-held of a marginal grasp is chaotic (docs/physics.md): validates every grasp of
/// `doc` `trials` − 1 more times with the hand moved and turned slightly (perturbed_grasp,
/// seed trial_seed + 1000·k + t for trial t of grasp k) and records all outcomes in
/// doc.trial_outcomes; `progress` is called after each grasp's trials.
/// @throws std::invalid_argument when trials is not in [1, 1000].
void add_perturbed_trials(SimDocument& doc, const PlanDocument& plan, const HandModel& hand,
                          const Mesh& mesh, int trials, const PerturbationParams& perturbation,
                          std::uint64_t seed, const ValidateProgress& progress = {});

/// How many of `outcomes` are held.
int count_held(const std::vector<Outcome>& outcomes);

/// Trials of a grasp that held: "held in 3 / 5 trials".
std::string trials_line(const std::vector<Outcome>& outcomes);

/// "held (lift held, shake held, gravity6 held) mass 0.12 kg, 0.41 s"
std::string sim_result_line(const SimResult& result);

/// Grasps that did not hold, by the first phase that failed (settle, close, lift, shake,
/// gravity6, in that order), and grasps whose preshape hand overlapped the object.
struct FailureCounts {
  std::vector<std::pair<std::string, int>> by_phase;
  int preshape_overlaps = 0;
};
FailureCounts count_failures(const std::vector<SimResult>& results);

/// "not held by phase: settle 0, close 2, lift 1, shake 0, gravity6 0; preshape overlaps 1"
std::string failures_line(const std::vector<SimResult>& results);

}  // namespace cordgrasp::cli
