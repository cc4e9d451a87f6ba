#pragma once
// `cordgrasp export` as a job: a plan's grasps to the formats other tools read: a MuJoCo scene
// (MJCF), moveit_msgs/Grasp messages (YAML) and posed meshes (glTF binary or OBJ).
// Formats and conventions: docs/export.md.
#include <string>
#include <vector>

#include "cordgrasp/core/hand_description.h"
#include "cordgrasp/sim/sim_params.h"

namespace cordgrasp {

/// The file formats of export_job().
enum class ExportFormat {
  kMjcf,    ///< one MuJoCo scene: hand, object, one keyframe per grasp (+ a folder of meshes)
  kMoveit,  ///< one YAML file: a list of moveit_msgs/Grasp, one per grasp
  kGlb,     ///< one glTF 2.0 binary per grasp: the posed hand and the object
  kObj,     ///< one Wavefront OBJ (+ MTL) per grasp: the posed hand and the object
};

/// "mjcf", "moveit", "glb" or "obj".
const char* to_string(ExportFormat format);

/// Parses to_string()'s names. @throws std::invalid_argument naming the accepted ones.
ExportFormat parse_export_format(const std::string& text);

/// Inputs and settings of export_job().
struct ExportJobParams {
  std::string plan;                          ///< plan.json written by `cordgrasp plan`
  ExportFormat format = ExportFormat::kMjcf;
  /// mjcf, moveit: the file to write; glb, obj: a folder (created), one grasp_K.<ext> each.
  std::string out;
  HandLoadOptions hand_load;                 ///< package:// directories of the hand's URDF
  int grasps = -1;                           ///< export only the first K grasps (< 0: all)
  std::string cache_dir;                     ///< mjcf: on-disk convex decomposition cache
  /// mjcf: object mass, density and squeeze factor over the plan's recorded ones (CLI --mass),
  /// as `cordgrasp validate` takes them; the scene's bounded close is computed with them.
  SimOverrides physics;
};

/// What export_job() wrote.
struct ExportOutcome {
  std::vector<std::string> files;  ///< every file written, the main one first
  int grasps = 0;                  ///< grasps exported
};

/// Reads p.plan (its hand and object), writes p.format to p.out.
/// @throws InputError naming the file (plan, hand, object, output) and the problem.
ExportOutcome export_job(const ExportJobParams& p);

}  // namespace cordgrasp
