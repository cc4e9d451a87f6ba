#include "cordgrasp/core/geometry_points.h"

namespace cordgrasp {

std::vector<Eigen::Vector3d> geometry_points(const Geometry& g) {
  std::vector<Eigen::Vector3d> out;
  auto corners = [&](const Eigen::Vector3d& half) {
    for (int i = 0; i < 8; ++i) {
      const Eigen::Vector3d s((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1);
      out.push_back(g.X_LG * half.cwiseProduct(s).eval());
    }
  };
  switch (g.kind) {
    case Geometry::Kind::kBox:
      corners(0.5 * g.box_size_m);
      break;
    case Geometry::Kind::kCylinder:
      corners(Eigen::Vector3d(g.radius_m, g.radius_m, 0.5 * g.length_m));
      break;
    case Geometry::Kind::kSphere:
      // Axis extremes in the link frame: their bounding box is the sphere's, whatever X_LG's
      // rotation.
      for (int a = 0; a < 3; ++a)
        for (double s : {-1.0, 1.0})
          out.push_back(g.X_LG.translation() + s * g.radius_m * Eigen::Vector3d::Unit(a));
      break;
    case Geometry::Kind::kMesh:
      if (g.mesh) {
        out.reserve(g.mesh->vertices.size());
        for (const auto& v : g.mesh->vertices) out.push_back(g.X_LG * v);
      }
      break;
  }
  return out;
}

void append_collision_points(const Link& link, std::vector<Eigen::Vector3d>& out) {
  for (const Geometry& g : link.collisions) {
    const auto pts = geometry_points(g);
    out.insert(out.end(), pts.begin(), pts.end());
  }
}

}  // namespace cordgrasp
