#pragma once
#include "cordgrasp/core/mesh.h"

namespace cordgrasp {

/// Topology counts of a triangle soup after welding vertices at identical coordinates.
struct MeshTopology {
  int vertices = 0;              ///< distinct referenced vertex positions V
  int edges = 0;                 ///< distinct undirected edges E
  int triangles = 0;             ///< triangles F (as given, degenerate ones included)
  int boundary_edges = 0;        ///< edges used by exactly one triangle
  int non_manifold_edges = 0;    ///< edges used by three or more triangles
  int misoriented_edges = 0;     ///< two-triangle edges both walk the same way (flipped faces)
  int components = 0;            ///< connected components (triangles sharing a vertex)
  int euler_characteristic = 0;  ///< V − E + F
  bool closed = false;  ///< watertight: every edge is used by exactly two triangles (and F > 0)
};

/// Counts boundary and non-manifold edges, components and V − E + F of `mesh`, welding
/// vertices with identical coordinates first (so a soup split per face still counts as joined).
MeshTopology mesh_topology(const Mesh& mesh);

}  // namespace cordgrasp
