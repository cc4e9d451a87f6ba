#pragma once
// Private to core: welded vertex ids and the undirected edge table of a triangle soup, shared
// by mesh_topology, closed_mesh_volume and orient_triangles.
#include <array>
#include <cstdint>
#include <vector>

#include "cordgrasp/core/mesh.h"

namespace cordgrasp::detail {

/// One use of an undirected edge by a triangle.
struct EdgeUse {
  int tri = 0;           ///< triangle index
  bool forward = false;  ///< the triangle walks the edge from its lower to its higher vertex id
};

/// Edge table of a soup after welding vertices at identical coordinates (linear time).
struct MeshEdges {
  std::vector<int> weld;                     ///< vertex index → welded id (vertex-index order)
  int welded_vertices = 0;                   ///< distinct referenced positions
  std::vector<std::array<int, 2>> edges;     ///< (lo, hi) welded ids, sorted
  std::vector<int> first_use;                ///< edges[e] is used by uses[first_use[e] ..
  std::vector<EdgeUse> uses;                 ///<   .. first_use[e + 1]) (CSR layout)
  std::vector<std::array<int, 3>> tri_edge;  ///< edge index of each triangle side, −1 if collapsed

  int use_count(int e) const { return first_use[e + 1] - first_use[e]; }
};

/// Welds referenced vertices with identical coordinates and builds the edge table.
MeshEdges build_mesh_edges(const Mesh& mesh);

}  // namespace cordgrasp::detail
