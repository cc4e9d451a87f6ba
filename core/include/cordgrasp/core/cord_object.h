#pragma once
#include <Eigen/Core>
#include <memory>

#include "cordgrasp/core/mesh.h"
#include "cordgrasp/core/mesh_bvh.h"

namespace cordgrasp {

/// What the exploration stage precomputes once per object (docs/algorithm.md §1).
struct CordObject {
  std::shared_ptr<const MeshBvh> bvh;                ///< slicing / ray structure
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  ///< C: vertex mean [m]
  double radius_m = 0.0;                             ///< r = max ‖V − C‖ [m]
};

/// C, r of the bounding sphere s(C, r) (docs/algorithm.md §1) and the BVH: `bvh` when given
/// (build_object_bvh of this mesh, e.g. the collider's), else built.
/// @throws std::invalid_argument for a mesh without triangles.
CordObject make_cord_object(const Mesh& mesh, std::shared_ptr<const MeshBvh> bvh = nullptr);

}  // namespace cordgrasp
