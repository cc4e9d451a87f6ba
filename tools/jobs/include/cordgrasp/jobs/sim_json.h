#pragma once
// sim.json: what `cordgrasp validate` and `run` write (a SimDocument, validate_plan.h).
//
// Layout (format_version 2), meters, radians, seconds, kilograms:
//   format: "cordgrasp-sim", format_version: 2, cordgrasp_version, backend (Bullet version)
//   inputs: {plan, hand: {name, path}, object: {path, name, units, scale, triangles}, plan_seed}
//   parameters: {tests, every SimParams field through its Serialize visitor (sim_params_to_json:
//                contact{mu, cone_edges, soft_finger_radius_m}, time_step_s, ...,
//                decomposition{..}, ...)}
//   object: {shape, parts, mass_kg, volume_m3, closed, com_m, principal_inertia_kgm2,
//            decomposition_s}
//   grasps: [{index (in the plan), outcome, failed_phase (null when held), detail, epsilon,
//             force_closure, wall_time_s, trials (with --trials N > 1: {count, held,
//             outcomes: [trial 0 = the plan as written, then perturbed copies]}),
//             hold_probability (with --uncertainty other than none: {p, low, high (Wilson
//               95 %), draws, held, threshold, decided, verdict (above, below, undecided),
//               sensitivity: {factors: [{factor, mean_score_failed, mean_score_held,
//               effect}], most_associated (null unless some draws held and some failed)},
//               wall_time_s, cpu_s, simulations (draws simulated), draw_results: [{trial,
//               outcome, failed_phase, hand_offset_G_m, hand_turn_G_rad, mu_factor,
//               mass_factor, com_offset_O_m, squeeze_factor, scores: {factor: standardized
//               draw}, wall_time_s, cpu_s}]}),
//             phases: [{name, outcome, detail, translation_m, rotation_rad, max_translation_m,
//                       in_contact, contact_count, max_contact_count, max_penetration_m,
//                       joint_efforts: {joint: N·m or N}, sim_time_s, wall_time_s, steps}]}]
//   summary: {grasps, held, outcomes: {held, slipped, dropped, unstable}, wall_time_s,
//             trials, held_trials (over every trial of every grasp)}
//   parameters also: trials, trial_offset_m, trial_turn_rad, trial_seed, uncertainty
//             (UncertaintyParams, null without --uncertainty) and hold_probability
//             (HoldProbabilityParams, null likewise)
//   complete: false when the validation was interrupted (SIGINT), with interrupted: "SIGINT";
//             grasps then holds only those whose every trial finished (json_completeness.h;
//             absent in older files: true)
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
#include "cordgrasp/jobs/validate_plan.h"

namespace cordgrasp {

/// Every SimParams field as JSON (units in the names), nested structs as objects.
nlohmann::json sim_params_to_json(const SimParams& params);

/// One SimResult as JSON (joint names from `hand`).
nlohmann::json sim_result_to_json(const SimResult& result, const HandModel& hand);

/// JSON of a validation (layout above).
nlohmann::json sim_to_json(const SimDocument& doc, const HandModel& hand);

/// Writes sim_to_json() atomically. @throws InputError.
void write_sim_file(const std::string& path, const SimDocument& doc, const HandModel& hand);

/// Parses sim.json. @throws InputError naming the file (missing, not JSON, not a sim file).
nlohmann::json read_sim_json(const std::string& path);

}  // namespace cordgrasp
