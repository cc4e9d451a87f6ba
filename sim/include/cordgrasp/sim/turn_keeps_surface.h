#pragma once
// Whether a turn of the object is one the fingers cannot tell from no turn (docs/physics.md §4):
// a body of revolution spinning about its axis, a sphere about any axis, a box by a quarter
// turn. The close and the tests judge such a turn by the object's centre of mass only.
#include <Eigen/Core>
#include <string>

#include "cordgrasp/core/mesh.h"

namespace cordgrasp {

/// An object's triangles in a tree, up to 128 of its vertices (evenly by index) and the
/// surface's area-weighted centroid, object frame.
struct ObjectSurface;

/// The surface of `mesh`, built on the first call per mesh content and kept for the process.
/// @throws std::invalid_argument for a mesh without a triangle of non-zero area.
const ObjectSurface& object_surface(const Mesh& mesh);
/// The same, for a caller that has the mesh's mesh_hash (convex_decomposition.h) already.
const ObjectSurface& object_surface(const Mesh& mesh, const std::string& mesh_key);

/// True when turning the object by R_O (object frame) about its surface's centroid leaves each
/// of the surface's vertices within tolerance_m of the unturned surface. The centroid, not the
/// centre of mass: a body of revolution's lies on its axis whatever its mass distribution.
bool turn_keeps_surface(const ObjectSurface& surface, const Eigen::Matrix3d& R_O,
                        double tolerance_m);

}  // namespace cordgrasp
