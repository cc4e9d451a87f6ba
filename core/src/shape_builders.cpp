#include "cordgrasp/core/shape_builders.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <tuple>

namespace cordgrasp {
namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

Mesh make_revolved_mesh(const std::vector<Eigen::Vector2d>& profile_rz, int segments) {
  if (profile_rz.size() < 2) throw std::invalid_argument("make_revolved_mesh: < 2 profile points");
  if (segments < 3) throw std::invalid_argument("make_revolved_mesh: segments < 3");
  Mesh m;
  m.name = "revolved";
  // ring[i][j]: vertex of profile point i at angle j (all j equal for a pole).
  std::vector<std::vector<int>> ring(profile_rz.size());
  for (size_t i = 0; i < profile_rz.size(); ++i) {
    const double r = profile_rz[i].x(), z = profile_rz[i].y();
    if (r < 0.0) throw std::invalid_argument("make_revolved_mesh: negative radius in profile");
    if (r == 0.0) {
      ring[i].assign(segments, int(m.vertices.size()));
      m.vertices.emplace_back(0.0, 0.0, z);
      continue;
    }
    for (int j = 0; j < segments; ++j) {
      const double phi = 2 * kPi * j / segments;
      ring[i].push_back(int(m.vertices.size()));
      m.vertices.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
    }
  }
  for (size_t i = 0; i + 1 < profile_rz.size(); ++i)
    for (int j = 0; j < segments; ++j) {
      const int k = (j + 1) % segments;
      const int a = ring[i][j], b = ring[i][k], c = ring[i + 1][k], d = ring[i + 1][j];
      if (a != b) m.triangles.emplace_back(a, b, c);  // skipped on a pole at i
      if (c != d) m.triangles.emplace_back(a, c, d);  // skipped on a pole at i + 1
    }
  return m;
}

Mesh make_swept_tube_mesh(const std::vector<Eigen::Vector3d>& path_m,
                          const std::vector<double>& radii_m, int segments) {
  const size_t n = path_m.size();
  if (n < 2 || radii_m.size() != n)
    throw std::invalid_argument("make_swept_tube_mesh: need >= 2 path points and one radius each");
  if (segments < 3) throw std::invalid_argument("make_swept_tube_mesh: segments < 3");
  std::vector<Eigen::Vector3d> dir(n - 1);
  for (size_t i = 0; i + 1 < n; ++i) {
    const Eigen::Vector3d d = path_m[i + 1] - path_m[i];
    if (d.norm() == 0.0) throw std::invalid_argument("make_swept_tube_mesh: repeated path point");
    dir[i] = d.normalized();
  }
  Mesh m;
  m.name = "tube";
  // Tangent at each point: mean of the adjacent segment directions.
  std::vector<Eigen::Vector3d> tangent(n);
  tangent[0] = dir.front();
  tangent[n - 1] = dir.back();
  for (size_t i = 1; i + 1 < n; ++i) tangent[i] = (dir[i - 1] + dir[i]).normalized();
  // Rotation-minimizing normal: project the previous normal onto each new cross-section plane.
  Eigen::Vector3d normal = tangent[0].unitOrthogonal();
  for (size_t i = 0; i < n; ++i) {
    normal = (normal - normal.dot(tangent[i]) * tangent[i]).normalized();
    const Eigen::Vector3d binormal = tangent[i].cross(normal);
    for (int j = 0; j < segments; ++j) {
      const double phi = 2 * kPi * j / segments;
      m.vertices.push_back(path_m[i] +
                           radii_m[i] * (std::cos(phi) * normal + std::sin(phi) * binormal));
    }
  }
  for (size_t i = 0; i + 1 < n; ++i)
    for (int j = 0; j < segments; ++j) {
      const int k = (j + 1) % segments;
      const int a = int(i) * segments + j, b = int(i) * segments + k;
      m.triangles.emplace_back(a, b, b + segments);
      m.triangles.emplace_back(a, b + segments, a + segments);
    }
  const int start = int(m.vertices.size());
  m.vertices.push_back(path_m.front());
  m.vertices.push_back(path_m.back());
  const int last = int(n - 1) * segments;
  for (int j = 0; j < segments; ++j) {
    const int k = (j + 1) % segments;
    m.triangles.emplace_back(start, k, j);
    m.triangles.emplace_back(start + 1, last + j, last + k);
  }
  return m;
}

Mesh make_swept_tube_mesh(const std::vector<Eigen::Vector3d>& path_m, double radius_m,
                          int segments) {
  return make_swept_tube_mesh(path_m, std::vector<double>(path_m.size(), radius_m), segments);
}

Mesh make_grid_box_mesh(const Eigen::Vector3d& size_m, double max_cell_m) {
  if (!(max_cell_m > 0.0)) throw std::invalid_argument("make_grid_box_mesh: max_cell_m <= 0");
  std::array<int, 3> cells;
  for (int a = 0; a < 3; ++a) {
    const double n = std::ceil(size_m[a] / max_cell_m - 1e-9);  // tolerate rounding of exact fits
    cells[a] = std::max(1, int(n));
  }
  Mesh m;
  m.name = "box";
  std::map<std::array<int, 3>, int> index_of;  // lattice point → vertex
  const auto vertex = [&](const std::array<int, 3>& q) {
    auto [it, inserted] = index_of.emplace(q, int(m.vertices.size()));
    if (inserted) {
      Eigen::Vector3d p;
      for (int a = 0; a < 3; ++a) p[a] = size_m[a] * (double(q[a]) / cells[a] - 0.5);
      m.vertices.push_back(p);
    }
    return it->second;
  };
  for (int a = 0; a < 3; ++a) {
    const int u = (a + 1) % 3, v = (a + 2) % 3;  // e_u × e_v = e_a
    for (int side = 0; side < 2; ++side)
      for (int i = 0; i < cells[u]; ++i)
        for (int j = 0; j < cells[v]; ++j) {
          std::array<int, 4> quad;
          const int du[4] = {0, 1, 1, 0}, dv[4] = {0, 0, 1, 1};
          for (int c = 0; c < 4; ++c) {
            std::array<int, 3> q;
            q[a] = side * cells[a];
            q[u] = i + du[c];
            q[v] = j + dv[c];
            quad[c] = vertex(q);
          }
          if (side == 0) std::swap(quad[1], quad[3]);  // face −e_a
          m.triangles.emplace_back(quad[0], quad[1], quad[2]);
          m.triangles.emplace_back(quad[0], quad[2], quad[3]);
        }
  }
  return m;
}

std::vector<Eigen::Vector2d> densify_polyline(const std::vector<Eigen::Vector2d>& points,
                                              double max_step) {
  std::vector<Eigen::Vector2d> out;
  for (size_t i = 0; i < points.size(); ++i) {
    if (i > 0) {
      const Eigen::Vector2d d = points[i] - points[i - 1];
      const int steps = std::max(1, int(std::ceil(d.norm() / max_step - 1e-9)));
      for (int s = 1; s < steps; ++s) out.push_back(points[i - 1] + d * (double(s) / steps));
    }
    out.push_back(points[i]);
  }
  return out;
}

}  // namespace cordgrasp
