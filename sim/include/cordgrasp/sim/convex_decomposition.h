#pragma once
#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "cordgrasp/core/mesh.h"
#include "cordgrasp/core/serialize.h"

namespace cordgrasp {

/// Parameters of the HACD convex decomposition (Bullet extras, K. Mamou 2011).
struct DecompositionParams {
  /// Largest concavity a part may have, as a fraction of the bounding-box diagonal [-].
  double concavity = 0.01;
  int min_parts = 1;               ///< HACD stops merging at this many parts
  int max_hull_vertices = 64;      ///< vertices per part hull (HACD simplifies beyond)
  double compacity_weight = 0.1;   ///< HACD α: favours compact parts
  double volume_weight = 0.0;      ///< HACD β
  /// Join disconnected components closer than this (fraction of the diagonal); < 0 = never.
  double connect_distance = 0.01;
  bool add_extra_distance_points = true;  ///< HACD: rays through the object (slow, robust)
  bool add_face_points = true;            ///< HACD: face centres as distance points
  /// HACD runs on a simplified copy (meshoptimizer's edge collapses, vertices where they
  /// were) with at most this many triangles: its cost grows much faster than linearly.
  /// ≤ 0: the whole mesh.
  int max_input_triangles = 800;

  /// Visits every field in declaration order (core/serialize.h).
  template <typename Archive>
  void Serialize(Archive* a) {
    visit_fields(a, CORDGRASP_NVP(concavity), CORDGRASP_NVP(min_parts),
                 CORDGRASP_NVP(max_hull_vertices), CORDGRASP_NVP(compacity_weight),
                 CORDGRASP_NVP(volume_weight), CORDGRASP_NVP(connect_distance),
                 CORDGRASP_NVP(add_extra_distance_points), CORDGRASP_NVP(add_face_points),
                 CORDGRASP_NVP(max_input_triangles));
  }
};

/// Convex parts of a mesh, in the mesh frame.
struct ConvexDecomposition {
  std::vector<std::vector<Eigen::Vector3d>> parts;  ///< hull vertices of each part [m]
  double compute_s = 0.0;   ///< wall time of the HACD run that produced it [s]
  bool from_cache = false;  ///< served from the memory or disk cache
};

/// HACD decomposition of a triangle soup (vertices welded at identical coordinates first,
/// simplified down to max_input_triangles); part hulls are reduced to max_hull_vertices
/// (simplified_convex_hull). A mesh HACD cannot handle gives one part: its convex hull.
/// Deterministic.
/// @throws std::invalid_argument for an empty mesh.
ConvexDecomposition convex_decomposition(const Mesh& mesh, const DecompositionParams& params);

/// convex_decomposition() cached in memory (per process, thread-safe) and, when `cache_dir` is
/// not empty, on disk as `<cache_dir>/<key>.hacd` (exact binary doubles; written atomically).
/// The key hashes the mesh's vertices, triangles and the parameters.
std::shared_ptr<const ConvexDecomposition> cached_convex_decomposition(
    const Mesh& mesh, const DecompositionParams& params, const std::string& cache_dir = "");

/// Vertices of the convex hull of `points`, reduced to at most `max_vertices` by HACD's
/// incremental hull (greedily adding the point that grows the volume most), so the reduced hull
/// lies inside the exact one and misses least volume. Fewer than 4 points: returned as given.
std::vector<Eigen::Vector3d> simplified_convex_hull(const std::vector<Eigen::Vector3d>& points,
                                                    int max_vertices);

/// simplified_convex_hull() for points that are already the vertices of their convex hull
/// (e.g. Qhull's): the reduction alone.
std::vector<Eigen::Vector3d> reduced_convex_hull(const std::vector<Eigen::Vector3d>& hull_vertices,
                                                 int max_vertices);

/// 64-bit hash of the mesh geometry (vertex coordinates and triangle indices; FNV-1a's step
/// over 8-byte words), as 16 hex digits.
std::string mesh_hash(const Mesh& mesh);

}  // namespace cordgrasp
