#pragma once
#include <Eigen/Core>

#include "cordgrasp/core/mesh.h"
#include "cordgrasp/core/mesh_bvh.h"

namespace cordgrasp {

/// What the exploration stage precomputes once per object (docs/algorithm.md §1).
struct CordObject {
  MeshBvh bvh;                                       ///< slicing / ray structure
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  ///< C: vertex mean [m]
  double radius_m = 0.0;                             ///< r = max ‖V − C‖ [m]
};

/// Builds the BVH and C, r of the bounding sphere s(C, r) (docs/algorithm.md §1).
/// @throws std::invalid_argument for a mesh without triangles.
CordObject make_cord_object(const Mesh& mesh);

}  // namespace cordgrasp
