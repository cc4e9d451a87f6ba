#include "mesh_ray_internal.h"

#include <algorithm>
#include <cmath>

namespace cordgrasp::internal {

std::vector<double> segment_hit_params(const Mesh& mesh, const Eigen::Vector3d& a,
                                       const Eigen::Vector3d& b) {
  constexpr double kMergeDistance_m = 1e-9;
  const Eigen::Vector3d d = b - a;
  const double length = d.norm();
  std::vector<double> ts;
  if (length <= 0.0) return ts;
  for (const Eigen::Vector3i& tri : mesh.triangles) {
    const Eigen::Vector3d& v0 = mesh.vertices[tri[0]];
    const Eigen::Vector3d e1 = mesh.vertices[tri[1]] - v0;
    const Eigen::Vector3d e2 = mesh.vertices[tri[2]] - v0;
    const Eigen::Vector3d p = d.cross(e2);
    const double det = e1.dot(p);
    const double scale = e1.norm() * e2.norm() * length;
    if (std::abs(det) <= 1e-14 * scale) continue;  // parallel or degenerate
    const double inv = 1.0 / det;
    const Eigen::Vector3d s = a - v0;
    const double u = s.dot(p) * inv;
    if (u < 0.0 || u > 1.0) continue;
    const Eigen::Vector3d qv = s.cross(e1);
    const double v = d.dot(qv) * inv;
    if (v < 0.0 || u + v > 1.0) continue;
    const double t = e2.dot(qv) * inv;
    if (t < 0.0 || t > 1.0) continue;
    ts.push_back(t);
  }
  std::sort(ts.begin(), ts.end());
  std::vector<double> out;
  for (double t : ts)
    if (out.empty() || (t - out.back()) * length > kMergeDistance_m) out.push_back(t);
  return out;
}

}  // namespace cordgrasp::internal
