#pragma once
#include <vector>

#include "cordgrasp/core/mesh.h"
#include "cordgrasp/core/mesh_volume.h"

namespace cordgrasp {

/// Volume and centroid of the convex hull of the mesh's referenced vertices (Qhull), e.g. for
/// the mass of an open mesh [m³, m]. Flat input (or fewer than 4 points) gives volume 0 and
/// the vertex mean as centroid. `hull_vertices`, when given, receives the hull's vertices in
/// Qhull's order (empty for flat input).
SolidVolume convex_hull_volume(const Mesh& mesh,
                               std::vector<Eigen::Vector3d>* hull_vertices = nullptr);

}  // namespace cordgrasp
