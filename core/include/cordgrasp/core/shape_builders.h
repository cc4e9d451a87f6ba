#pragma once
#include <Eigen/Core>
#include <vector>

#include "cordgrasp/core/mesh.h"

namespace cordgrasp {

/// Surface of revolution about the z axis of a profile of (r, z) points [m], `segments` around.
/// Walk the profile with the solid on the left (counter-clockwise in the (r, z) half-plane, e.g.
/// (0, 0) → (R, 0) → (R, H) → (0, H)) to get outward triangles. Points with r = 0 become single
/// pole vertices; a profile that starts and ends on the axis (and nowhere else) gives a closed
/// surface. @throws std::invalid_argument for fewer than 2 points, r < 0 or segments < 3.
Mesh make_revolved_mesh(const std::vector<Eigen::Vector2d>& profile_rz, int segments = 48);

/// Closed tube of circular cross-section swept along a polyline `path_m` (at least 2 points),
/// with radius radii_m[i] at path point i [m], rotation-minimizing frames and flat end caps;
/// outward triangles. The path should bend slowly compared with the radius.
/// @throws std::invalid_argument for mismatched sizes, repeated points or segments < 3.
Mesh make_swept_tube_mesh(const std::vector<Eigen::Vector3d>& path_m,
                          const std::vector<double>& radii_m, int segments = 16);

/// make_swept_tube_mesh() with one radius along the whole path [m].
Mesh make_swept_tube_mesh(const std::vector<Eigen::Vector3d>& path_m, double radius_m,
                          int segments = 16);

/// Closed box centred at the origin with full extents `size_m` [m], each face split into a grid
/// of cells no larger than `max_cell_m` [m] (vertices shared along the box edges); outward.
Mesh make_grid_box_mesh(const Eigen::Vector3d& size_m, double max_cell_m);

/// Inserts points into a polyline so that no segment is longer than `max_step` (same units).
std::vector<Eigen::Vector2d> densify_polyline(const std::vector<Eigen::Vector2d>& points,
                                              double max_step);

}  // namespace cordgrasp
