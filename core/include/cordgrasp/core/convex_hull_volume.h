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

/// The same for a set of points (the mean of the points as centroid of flat input).
SolidVolume convex_hull_volume(const std::vector<Eigen::Vector3d>& points,
                               std::vector<Eigen::Vector3d>* hull_vertices = nullptr);

/// The points lowest and highest in their column, for columns along each of x, y and z on a
/// grid of square cells, `cells` of them along the bounding box's longest side; in their input
/// order, each once. Every other point lies on a segment between two of them in its column, so
/// within √2 cell widths of their convex hull: the hull of a scan of millions of vertices at a
/// bounded cost (at most 6 · cells² points). Fewer than 4 points or cells < 1: all of them.
std::vector<Eigen::Vector3d> column_extreme_points(const std::vector<Eigen::Vector3d>& points,
                                                   int cells);

}  // namespace cordgrasp
