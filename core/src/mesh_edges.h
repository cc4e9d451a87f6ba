#pragma once
// Private to core: welded vertex ids and the edge sharing of a triangle soup, shared by
// mesh_topology, closed_mesh_volume and orient_triangles.
#include <vector>

#include "cordgrasp/core/mesh.h"

namespace cordgrasp::detail {

/// How the triangle sides of a soup share undirected edges, after welding vertices at identical
/// coordinates (linear time). A side is named by its code 3·triangle + side (side s runs from
/// corner s to corner s + 1).
struct MeshEdges {
  static constexpr int kBoundary = -1;     ///< the side's edge is used by this side only
  static constexpr int kNonManifold = -2;  ///< the side's edge is used by three or more sides
  static constexpr int kCollapsed = -3;    ///< both ends weld to one vertex: not an edge

  std::vector<int> weld;    ///< vertex index → welded id (vertex-index order), −1 if unused
  int welded_vertices = 0;  ///< distinct referenced positions
  /// Per side code: the other side of its edge when exactly two sides use the edge, else one of
  /// kBoundary, kNonManifold, kCollapsed.
  std::vector<int> twin;
  int edges = 0;               ///< distinct undirected edges
  int boundary_edges = 0;      ///< edges used by one side
  int non_manifold_edges = 0;  ///< edges used by three or more sides

  /// Every edge is shared by exactly two triangle sides (mesh_topology's `closed`, given
  /// triangles).
  bool every_edge_used_twice() const { return boundary_edges == 0 && non_manifold_edges == 0; }
  /// The side walks its edge from the lower to the higher welded id.
  bool forward(const Mesh& mesh, int side_code) const {
    const Eigen::Vector3i& t = mesh.triangles[size_t(side_code / 3)];
    const int s = side_code % 3;
    return weld[size_t(t[s])] < weld[size_t(t[(s + 1) % 3])];
  }
};

/// Welds referenced vertices with identical coordinates and pairs the triangle sides.
MeshEdges build_mesh_edges(const Mesh& mesh);

/// Which triangles orient_triangles() reverses, without changing the mesh.
struct OrientationFlips {
  std::vector<char> flip;  ///< per triangle: 1 if its winding is to be reversed
  int patches = 0;
  int closed_patches = 0;
  bool orientable = true;
};

/// orient_triangles()'s decision for `mesh` from its edge sharing `me`.
OrientationFlips orientation_flips(const Mesh& mesh, const MeshEdges& me);

}  // namespace cordgrasp::detail
