#pragma once
// plan.json: what `cordgrasp plan` writes and `validate`, `render` and `run` read back.
//
// Layout (format_version 2), all lengths in meters, angles in radians:
//   format: "cordgrasp-plan", format_version: 2, cordgrasp_version
//   inputs: {hand: {name, path, urdf_path}, object: {path, name, units, scale, triangles}}
//   parameters: {planner, every PlanParams field (grasps, time_limit_s, seed, finger{..},
//                quality{contact{mu, cone_edges, soft_finger_radius_m}, mode, ..}, ..),
//                palm_width_m, cord: every CordParams field (null for the generic planner)},
//                written and read through the structs' Serialize visitors (every key required)
//   stats: {every PlanStats field but interrupted (first_force_closure_s null if none; a
//           count absent from an older file reads as 0), machine_dependent (= timed_out: the
//           --time-limit safety net fired, so another machine may find other grasps with the
//           same seed)}
//   grasps: [{hand_pose: {position_m: [x,y,z], quaternion_wxyz: [w,x,y,z]}  (root link in the
//             object frame), gcp_pose: {same, GCP in the object frame},
//             joints: {name: value} (after closing), preshape_joints: {name: value},
//             contacts: [{link, point_m, normal}] (object frame, normal out of the object),
//             force_closure, epsilon, alpha_rad (α of the palm normal; GCP z for a hand
//             without one), alpha_approach_rad (α of the GCP z axis; when absent, as
//             alpha_rad), chi_m2 (null: generic), region_rank (null),
//             region (null: generic; layout of region_json.h: cords, P1, P_l, P_r, ...),
//             timings_s: {exploration, finger, quality},
//             validation (validated plans only): every GraspValidation field}]
//   validation (validated plans only): {parameters: every ValidationParams field,
//                                        stats: every ValidationStats field}
//   complete: false when the planning was interrupted (SIGINT), with interrupted: "SIGINT"; the
//             grasps are those found before (json_completeness.h; absent in older files: true)
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cordgrasp/core/cord_params.h"
#include "cordgrasp/core/grasp.h"
#include "cordgrasp/core/grasp_plan.h"
#include "cordgrasp/core/hand_model.h"
#include "cordgrasp/sim/grasp_validation.h"

namespace cordgrasp {

/// Everything plan.json holds besides the grasps' raw joint vectors.
struct PlanDocument {
  std::string cordgrasp_version;
  std::string hand_name;    ///< HandModel::name
  std::string hand_path;    ///< absolute path of the hand description file
  std::string urdf_path;    ///< absolute path of its URDF
  std::string object_path;  ///< absolute path of the object mesh
  std::string object_name;
  std::string object_units = "m";  ///< as given to --units (m, mm or auto)
  double object_scale = 1.0;       ///< as given to --scale (applied after the units)
  int object_triangles = 0;
  PlannerKind planner = PlannerKind::kCord;
  PlanParams params;             ///< as planned; params.quality.contact is the ContactModel
  double palm_width_m = 0.0;     ///< palm width of the hand (cord exploration) [m]
  std::optional<CordParams> cord;  ///< cord planner: exploration as run (seed, time limit)
  PlanStats stats;
  std::vector<Grasp> grasps;
  /// Validated planning (plan_validated_grasps): its settings, counts and one verdict per grasp;
  /// unset for a plan of force-closure grasps only.
  std::optional<PlanValidation> validation;
  /// The signal that stopped the planning early ("SIGINT"); "" when it ran to its end.
  std::string interrupted;
};

/// JSON of a plan (layout above); joint and link names come from `hand`.
nlohmann::json plan_to_json(const PlanDocument& plan, const HandModel& hand);

/// Writes plan_to_json() to `path` atomically (temp file + rename). @throws InputError.
void write_plan_file(const std::string& path, const PlanDocument& plan, const HandModel& hand);

/// Parses plan.json text from `path`, format 2 upgraded to the current 3
/// (upgrade_plan_from_version_2). @throws InputError naming the file (missing, not JSON, not a
/// cordgrasp plan, unsupported format_version: version 1 files are refused).
nlohmann::json read_plan_json(const std::string& path);

/// The one upgrade step of plan.json format 2 to 3: drops the candidate filters
/// (parameters.candidate, stats.filtered; they only chose which grasps were planned) and adds
/// what early version-2 plans lack, as version 2 read it (inputs.object.scale 1, the grasps'
/// preshape_joints {}, alpha_approach_rad = alpha_rad, default measures; no validation
/// physics_file) and moves validated planning's diversity rule to parameters.diversity (plain
/// version-2 plans had none: all 0).
void upgrade_plan_from_version_2(nlohmann::json* plan);

/// Hand description path recorded in a plan (to load the hand before plan_from_json).
std::string plan_hand_path(const nlohmann::json& plan);

/// Object mesh path recorded in a plan.
std::string plan_object_path(const nlohmann::json& plan);

/// Decodes a plan for `hand`; `source` (the file name) starts error messages. @throws
/// InputError when the plan was made for another hand (name differs), names a joint or link
/// the hand does not have, or its parameters miss a key ("plan.json: parameters.seed:
/// missing"), hold an unknown one or a wrong type.
PlanDocument plan_from_json(const nlohmann::json& plan, const HandModel& hand,
                            const std::string& source = "plan");

}  // namespace cordgrasp
