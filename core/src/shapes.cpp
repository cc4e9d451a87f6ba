#include "cordgrasp/core/shapes.h"

#include <cmath>

namespace cordgrasp {
namespace {
constexpr double kPi = 3.14159265358979323846;

/// Grid of (rows+1)×(cols) vertices wrapped in the column direction, quads split in two.
/// Vertex (i, j) is at index base + i·cols + j.
void add_wrapped_grid(Mesh& m, int base, int rows, int cols) {
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      const int a = base + i * cols + j, b = base + i * cols + (j + 1) % cols;
      const int c = a + cols, d = b + cols;
      m.triangles.emplace_back(a, b, d);
      m.triangles.emplace_back(a, d, c);
    }
}
}  // namespace

Mesh make_box_mesh(const Eigen::Vector3d& size_m) {
  Mesh m;
  m.name = "box";
  const Eigen::Vector3d h = 0.5 * size_m;
  for (int i = 0; i < 8; ++i)
    m.vertices.emplace_back((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(),
                            (i & 4) ? h.z() : -h.z());
  m.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                 {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return m;
}

Mesh make_cylinder_mesh(double radius_m, double length_m, int segments) {
  Mesh m;
  m.name = "cylinder";
  for (int ring = 0; ring < 2; ++ring)
    for (int j = 0; j < segments; ++j) {
      const double phi = 2 * kPi * j / segments;
      m.vertices.emplace_back(radius_m * std::cos(phi), radius_m * std::sin(phi),
                              (ring - 0.5) * length_m);
    }
  add_wrapped_grid(m, 0, 1, segments);
  const int bottom = int(m.vertices.size());
  m.vertices.emplace_back(0, 0, -0.5 * length_m);
  m.vertices.emplace_back(0, 0, 0.5 * length_m);
  for (int j = 0; j < segments; ++j) {
    const int k = (j + 1) % segments;
    m.triangles.emplace_back(bottom, k, j);
    m.triangles.emplace_back(bottom + 1, segments + j, segments + k);
  }
  return m;
}

Mesh make_sphere_mesh(double radius_m, int rings, int segments) {
  Mesh m;
  m.name = "sphere";
  // Rings 1..rings-1 between the poles.
  for (int i = 1; i < rings; ++i) {
    const double theta = kPi * i / rings;
    for (int j = 0; j < segments; ++j) {
      const double phi = 2 * kPi * j / segments;
      m.vertices.emplace_back(radius_m * std::sin(theta) * std::cos(phi),
                              radius_m * std::sin(theta) * std::sin(phi),
                              radius_m * std::cos(theta));
    }
  }
  add_wrapped_grid(m, 0, rings - 2, segments);
  // The grid above runs from +z toward −z with (a, b, d) winding; flip it to face outward.
  for (auto& t : m.triangles) std::swap(t[1], t[2]);
  const int north = int(m.vertices.size());
  m.vertices.emplace_back(0, 0, radius_m);
  m.vertices.emplace_back(0, 0, -radius_m);
  const int last = (rings - 2) * segments;
  for (int j = 0; j < segments; ++j) {
    const int k = (j + 1) % segments;
    m.triangles.emplace_back(north, j, k);
    m.triangles.emplace_back(north + 1, last + k, last + j);
  }
  return m;
}

Mesh make_torus_mesh(double major_m, double minor_m, int major_segments, int minor_segments) {
  Mesh m;
  m.name = "torus";
  for (int i = 0; i < major_segments; ++i) {
    const double u = 2 * kPi * i / major_segments;
    for (int j = 0; j < minor_segments; ++j) {
      const double v = 2 * kPi * j / minor_segments;
      const double rho = major_m + minor_m * std::cos(v);
      m.vertices.emplace_back(rho * std::cos(u), rho * std::sin(u), minor_m * std::sin(v));
    }
  }
  for (int i = 0; i < major_segments; ++i)
    for (int j = 0; j < minor_segments; ++j) {
      const int i1 = (i + 1) % major_segments, j1 = (j + 1) % minor_segments;
      const int a = i * minor_segments + j, b = i1 * minor_segments + j;
      const int c = i1 * minor_segments + j1, d = i * minor_segments + j1;
      m.triangles.emplace_back(a, b, c);
      m.triangles.emplace_back(a, c, d);
    }
  return m;
}

void append_mesh(Mesh& a, const Mesh& b, const Eigen::Isometry3d& X_AB) {
  const int base = int(a.vertices.size());
  for (const auto& v : b.vertices) a.vertices.push_back(X_AB * v);
  for (const auto& t : b.triangles) a.triangles.emplace_back(t.array() + base);
}

}  // namespace cordgrasp
