#pragma once
#include <Eigen/Core>
#include <vector>

#include "cordgrasp/core/hand_model.h"

namespace cordgrasp {

/// Points spanning a link geometry's extent, in the link frame [m]: box corners, the corners of a
/// cylinder's bounding box, a sphere's six axis extremes (along the link axes), or a mesh's
/// vertices. Their link-frame bounding box contains the geometry (tight for boxes, spheres and
/// meshes, conservative for cylinders); use them for extents and sizes, not for contact.
std::vector<Eigen::Vector3d> geometry_points(const Geometry& geometry);

/// geometry_points() of every collision element of `link`, appended to `out` [m, link frame].
void append_collision_points(const Link& link, std::vector<Eigen::Vector3d>& out);

}  // namespace cordgrasp
