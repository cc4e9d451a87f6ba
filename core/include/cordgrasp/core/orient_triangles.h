#pragma once
#include "cordgrasp/core/mesh.h"

namespace cordgrasp {

/// What orient_triangles() changed.
struct OrientReport {
  int flipped = 0;         ///< triangles whose winding was reversed
  int patches = 0;         ///< edge-connected patches (through two-triangle edges)
  int closed_patches = 0;  ///< patches whose every edge is shared by exactly two triangles
  bool orientable = true;  ///< false when some patch cannot be oriented (Möbius-like)
};

/// Makes triangle winding consistent across every edge shared by exactly two triangles (BFS
/// over such edges, after welding identical vertex positions). Each closed patch is then turned
/// outward (positive signed volume); an open patch keeps the orientation of most of its
/// triangles as authored. Boundary and non-manifold edges are not crossed.
OrientReport orient_triangles(Mesh& mesh);

}  // namespace cordgrasp
