#pragma once
#include <Eigen/Core>
#include <vector>

#include "cordgrasp/core/mesh.h"

namespace cordgrasp {

/// Bounding-volume hierarchy over a triangle soup, used to slice it with planes (docs/algorithm.md
/// §2.1) and to cast segments against it (docs/algorithm.md §2.2). Holds its own copy of the
/// geometry.
struct MeshBvh {
  /// One cache line: a query reads one line per node it visits.
  struct alignas(64) Node {
    Eigen::Vector3d lo = Eigen::Vector3d::Zero();  ///< box min [m]
    Eigen::Vector3d hi = Eigen::Vector3d::Zero();  ///< box max [m]
    double radius = 0.0;                           ///< ‖half()‖: bounding-sphere radius [m]
    int first = 0;  ///< leaf: first index into `triangles`; inner node: index of right child
    int count = 0;  ///< leaf: number of triangles; 0 marks an inner node (left child = own + 1)
    Eigen::Vector3d center() const { return 0.5 * (lo + hi); }  ///< [m]
    Eigen::Vector3d half() const { return 0.5 * (hi - lo); }    ///< [m]
  };
  std::vector<Node> nodes;                 ///< nodes[0] is the root; empty for an empty mesh
  /// Mesh::vertices, same indices; build_object_bvh of a large mesh: the used ones, numbered
  /// in first use along the leaves [m]
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> triangles;  ///< Mesh::triangles in leaf order
  std::vector<int> triangle_ids;           ///< index in Mesh::triangles of triangles[k]
};

/// How build_mesh_bvh orders triangles along the split axis.
enum class MeshBvhSplit {
  kCentroidThenIndex,  ///< centroid coordinate, ties by triangle index
  /// Sum of the corner coordinates, ties as std::nth_element leaves them; centroids for the
  /// axis choice as sum·(1/3). The order the hand–object collider has always visited triangles
  /// in: its closest-point witnesses on flat contacts (equal-distance triangles) depend on it.
  kCornerSum,
};

/// Builds a median-split BVH (longest centroid axis) with at most `max_leaf_triangles` per leaf.
/// Deterministic. @throws std::invalid_argument when max_leaf_triangles < 1.
MeshBvh build_mesh_bvh(const Mesh& mesh, int max_leaf_triangles = 4,
                       MeshBvhSplit split = MeshBvhSplit::kCentroidThenIndex);

/// Triangles above which build_object_bvh puts up to kLargeMeshLeafTriangles in a leaf.
constexpr int kLargeMeshTriangles = 200000;
/// Leaf size of a large mesh's object BVH: a quarter of the nodes (112 B each) of 4 per leaf.
constexpr int kLargeMeshLeafTriangles = 16;

/// The object's BVH that the cord exploration and the hand–object collider share (one copy
/// for a scan of millions of triangles): the triangles of non-zero area, corner-sum order,
/// at most 4 per leaf (kLargeMeshLeafTriangles above kLargeMeshTriangles: raw scans, whose
/// used vertices are then renumbered in first use along the leaves, so that a query reads
/// neighbouring memory); triangle_ids index mesh.triangles. Empty when no triangle has an area.
/// threads > 1: a large mesh's two halves are built at once (the same BVH).
MeshBvh build_object_bvh(const Mesh& mesh, int threads = 1);

}  // namespace cordgrasp
