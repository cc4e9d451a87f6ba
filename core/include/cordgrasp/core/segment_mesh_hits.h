#pragma once
#include <Eigen/Core>
#include <vector>

#include "cordgrasp/core/mesh.h"
#include "cordgrasp/core/mesh_bvh.h"

namespace cordgrasp {

/// One intersection of a segment with a soup triangle.
struct SegmentHit {
  double t = 0.0;  ///< parameter along the segment, point = p0 + t·(p1 − p0), t ∈ [0, 1]
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< [m]
  int triangle = -1;  ///< index in Mesh::triangles (first of merged duplicates)
};

/// Options of Primitive B (docs/algorithm.md §2.2).
struct SegmentHitOptions {
  double merge_m = 1e-9;          ///< hits closer than this along the segment are merged [m]
  double ignore_near_p0_m = 0.0;  ///< drop hits within this distance of p0 (ε_self = 1e-7 for
                                  ///< an on-surface origin) [m]
};

/// Primitive B (docs/algorithm.md §2.2): all hits of segment p0→p1 with the soup, two-sided
/// Möller–Trumbore in double precision, sorted by t, merged within `merge_m`. Brute force over all
/// triangles.
std::vector<SegmentHit> segment_mesh_hits(const Mesh& mesh, const Eigen::Vector3d& p0,
                                          const Eigen::Vector3d& p1,
                                          const SegmentHitOptions& options = {});

/// Primitive B accelerated by a BVH; same hits as the brute-force overload.
std::vector<SegmentHit> segment_mesh_hits(const MeshBvh& bvh, const Eigen::Vector3d& p0,
                                          const Eigen::Vector3d& p1,
                                          const SegmentHitOptions& options = {});

/// True when segment p0→p1 hits the soup farther than `margin_m` from both ends (Primitive B
/// with early exit; same predicate as segment_mesh_hits).
bool segment_meets_mesh(const MeshBvh& bvh, const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                        double margin_m = 1e-9);

}  // namespace cordgrasp
