#pragma once
// A grasp as one mesh file: the posed hand (visual geometry) and the object, object frame.
#include <string>

#include "cordgrasp/core/grasp.h"
#include "cordgrasp/core/hand_model.h"
#include "cordgrasp/core/mesh.h"

namespace cordgrasp {

/// Writes the object and the hand at grasp.X_OB with joints grasp.q (couplings applied), one
/// mesh per link geometry plus "object", in meters in the object frame, through assimp's
/// exporter: `format_id` "glb2" (glTF 2.0 binary) or "obj" (with an .mtl beside it).
/// @throws InputError naming `path` when assimp cannot write it; std::invalid_argument for
/// another format or a grasp that does not fit the hand.
void write_grasp_mesh(const std::string& path, const std::string& format_id,
                      const HandModel& hand, const Grasp& grasp, const Mesh& object);

}  // namespace cordgrasp
