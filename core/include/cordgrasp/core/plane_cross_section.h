#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "cordgrasp/core/guide_frame.h"
#include "cordgrasp/core/mesh.h"
#include "cordgrasp/core/mesh_bvh.h"

namespace cordgrasp {

/// 2D segment in plane coordinates [m].
struct Segment2 {
  Eigen::Vector2d a = Eigen::Vector2d::Zero();
  Eigen::Vector2d b = Eigen::Vector2d::Zero();
};

/// Planar cross-section of a triangle soup (docs/algorithm.md §2.1), in the plane's 2D
/// coordinates.
struct CrossSection {
  std::vector<Segment2> segments;       ///< S: one segment per mixed-sign triangle [m]
  std::vector<Eigen::Vector2d> points;  ///< V_S: segment endpoints, shared-edge crossings merged
};

/// Primitive A (docs/algorithm.md §2.1) by brute force over all triangles: vertex sign s = ν·(X−O)
/// > 0 is "+", else "−"; each mixed triangle gives the segment between its two mixed-edge
/// crossings, each computed from the lower-indexed vertex so shared edges give bit-identical
/// points.
CrossSection plane_cross_section(const Mesh& mesh, const PlaneFrame& plane);

/// Same result as the brute-force overload (same segments, possibly in another order), visiting
/// only BVH nodes the plane straddles.
CrossSection plane_cross_section(const MeshBvh& bvh, const PlaneFrame& plane);

/// Hot-path form of Primitive A: appends S to `segments` (V_S not built; endpoints of segments
/// that share a mesh edge are bit-identical, so duplicates are exact). With `region`
/// (a counter-clockwise triangle in plane coordinates), BVH nodes whose bounding sphere cannot
/// meet it are skipped: the result is then a superset of the segments meeting the region.
void append_plane_cross_section_segments(const MeshBvh& bvh, const PlaneFrame& plane,
                                         std::vector<Segment2>& segments,
                                         const Eigen::Vector2d* region = nullptr);

}  // namespace cordgrasp
