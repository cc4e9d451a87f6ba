#pragma once
#include <Eigen/Core>
#include <optional>

#include "cordgrasp/core/mesh.h"

namespace cordgrasp {

/// Volume and centre of mass of a uniform-density solid, in the mesh's frame.
struct SolidVolume {
  double volume_m3 = 0.0;                                      ///< [m³]
  Eigen::Vector3d center_of_mass_m = Eigen::Vector3d::Zero();  ///< [m]
};

/// Volume and centre of mass of the solid bounded by a closed (watertight) mesh, by the
/// divergence theorem after orient_triangles() (so flipped faces in the soup do not matter).
/// Closed parts of a soup are summed, so overlapping parts count twice and a nested cavity
/// adds instead of subtracting. Empty when the mesh is not closed (mesh_topology().closed),
/// is not orientable, or bounds no volume.
std::optional<SolidVolume> closed_mesh_volume(const Mesh& mesh);

}  // namespace cordgrasp
