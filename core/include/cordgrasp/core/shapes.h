#pragma once
#include "cordgrasp/core/mesh.h"

namespace cordgrasp {

/// Closed box centred at the origin with full extents `size_m` [m]; 12 outward triangles.
Mesh make_box_mesh(const Eigen::Vector3d& size_m);

/// Closed cylinder along z, centred at the origin, `segments` around [m]; outward triangles.
Mesh make_cylinder_mesh(double radius_m, double length_m, int segments = 48);

/// Closed UV sphere centred at the origin; every vertex exactly at `radius_m` (up to rounding).
Mesh make_sphere_mesh(double radius_m, int rings = 24, int segments = 48);

/// Closed torus around z centred at the origin: ring radius `major_m`, tube radius `minor_m`.
Mesh make_torus_mesh(double major_m, double minor_m, int major_segments = 48,
                     int minor_segments = 24);

/// Appends `b` (transformed by X_AB) to `a`, as a soup (no welding).
void append_mesh(Mesh& a, const Mesh& b,
                 const Eigen::Isometry3d& X_AB = Eigen::Isometry3d::Identity());

}  // namespace cordgrasp
