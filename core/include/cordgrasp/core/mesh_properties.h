#pragma once
#include <Eigen/Core>
#include <optional>

#include "cordgrasp/core/mesh.h"

namespace cordgrasp {

/// Axis-aligned bounding box [m].
struct Aabb {
  Eigen::Vector3d min = Eigen::Vector3d::Zero();
  Eigen::Vector3d max = Eigen::Vector3d::Zero();
  Eigen::Vector3d size() const { return max - min; }
  Eigen::Vector3d center() const { return 0.5 * (min + max); }
};

/// Axis-aligned bounds of all vertices [m]. Empty mesh gives a zero box.
Aabb mesh_bounds(const Mesh& mesh);

/// Barycenter C: the vertex mean, as Simox TriMeshModel::getCOM (docs/algorithm.md §1) [m].
Eigen::Vector3d vertex_mean(const Mesh& mesh);

/// The vertices that some triangle uses, in index order.
std::vector<Eigen::Vector3d> referenced_vertices(const Mesh& mesh);

/// Bounding-sphere radius r = max ‖V − C‖ over vertices (docs/algorithm.md §1) [m].
double bounding_radius(const Mesh& mesh, const Eigen::Vector3d& center);

/// Area-weighted surface principal axes (docs/algorithm.md §9).
struct PrincipalAxes {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  ///< area-weighted centroid ḡ [m]
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  ///< unit columns, descending variance
  Eigen::Vector3d variances = Eigen::Vector3d::Zero(); ///< eigenvalues of Σ, descending [m²]
  double area_m2 = 0.0;                                ///< total surface area [m²]
};

/// Area-weighted surface covariance eigen-decomposition (docs/algorithm.md §9); axes.col(0) is the
/// object's largest principal axis. Works on soups.
PrincipalAxes principal_axes(const Mesh& mesh);

/// Surface area of the soup [m²].
double surface_area(const Mesh& mesh);

}  // namespace cordgrasp
