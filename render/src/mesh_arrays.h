#pragma once
// Private to cordgrasp::render: CPU-side vertex arrays for drawing meshes.
#include <vector>

#include "cordgrasp/core/mesh.h"

namespace cordgrasp::render_detail {

/// Interleaved float array (px, py, pz, nx, ny, nz) per corner, 3 corners per triangle, for
/// glDrawArrays. Normals are angle-weighted averages over the triangles around each welded
/// vertex whose normals are within `crease_angle_rad` of the corner's own triangle (so flat
/// faces stay flat and curved surfaces smooth); degenerate triangles get a zero normal.
std::vector<float> smooth_vertex_array(const Mesh& mesh, double crease_angle_rad);

/// Closed cone: apex (0, 0, 1), base circle of radius 1 at z = 0 with a cap; or, open, the
/// lateral surface only with apex at the origin and base radius 1 at z = 1 (friction cones).
Mesh make_unit_cone_mesh(bool closed_arrow_head, int segments = 32);

}  // namespace cordgrasp::render_detail
