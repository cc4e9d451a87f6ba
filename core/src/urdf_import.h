#pragma once
// Internal to hand loading: a URDF (urdfdom) as the kinematic tree, geometry and inertials of a
// HandModel.
#include <string>

#include "cordgrasp/core/hand_description.h"
#include "cordgrasp/core/hand_model.h"

namespace cordgrasp::hand_load {

/// HandModel with links, joints (depth-first from the root: a joint's parent link precedes it),
/// root_link and urdf_path from the URDF; geometry meshes loaded in meters (package:// URIs via
/// `options`), implausible inertials substituted (Inertial::substituted; no warning printed).
/// The description's fields (GCP, actors, preshape, ...) are left at their defaults. The tree
/// is walked without recursion.
/// @throws InputError "load_hand: '<urdf>': ..." on a parse error, missing mesh or package,
///         joints forming a cycle or a link with two parent joints, bad limits or axes, mimic
///         errors, or no moving joint.
HandModel import_urdf(const std::string& urdf_path, const HandLoadOptions& options = {});

}  // namespace cordgrasp::hand_load
