#pragma once
// Loading a hand: the hand description (YAML, docs/hand-description.md) and the URDF it names.
#include <map>
#include <string>

#include "cordgrasp/core/hand_model.h"

namespace cordgrasp {

/// Options of load_hand.
struct HandLoadOptions {
  /// ROS package name → its directory, for package://NAME/... mesh URIs in the URDF; searched
  /// before $ROS_PACKAGE_PATH and $AMENT_PREFIX_PATH (docs/hand-description.md).
  std::map<std::string, std::string> package_paths;
};

/// Loads a hand description (YAML, format in docs/hand-description.md; `name_or_path` as for
/// resolve_hand_path) and the URDF it names (parsed with urdfdom), with all collision/visual
/// meshes in meters. Missing, placeholder or impossible inertials are replaced
/// (Inertial::substituted; one warning per hand on stderr).
/// @throws InputError naming the file and the problem (missing URDF or mesh, unknown ROS
///         package, joints forming a cycle, GCP link not found, preshape naming an unknown
///         joint, inverted limits, ...).
HandModel load_hand(const std::string& name_or_path, const HandLoadOptions& options = {});

}  // namespace cordgrasp
