#pragma once
// Helpers shared by the cord tests: guide-triangle sampling, polyline distances, an
// independent convex hull, test shapes.
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include "cordgrasp/core/cord_object.h"
#include "cordgrasp/core/guide_frame.h"
#include "cordgrasp/core/shapes.h"

namespace cordgrasp::test {

struct GuideTriangle {
  Eigen::Vector3d p1, p2, p3;
};

/// Uniform unit vector (test-side generator, independent of the library's).
inline Eigen::Vector3d random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  Eigen::Vector3d v;
  do v = Eigen::Vector3d(n(rng), n(rng), n(rng));
  while (v.norm() < 1e-6);
  return v.normalized();
}

/// Acute guide triangle drawn as Algorithm 1 does: P1 on s1 (r + 0.105), P2, P3 on s2 (r + 0.005).
inline GuideTriangle random_guide_triangle(const CordObject& object, std::mt19937_64& rng) {
  const double r2 = object.radius_m + 0.005, r1 = r2 + 0.10;
  for (;;) {
    const GuideTriangle t{object.center + r1 * random_unit(rng),
                          object.center + r2 * random_unit(rng),
                          object.center + r2 * random_unit(rng)};
    if (is_acute_triangle(t.p1, t.p2, t.p3)) return t;
  }
}

/// Distance from point p to segment [a, b].
template <typename V>
double point_segment_distance(const V& p, const V& a, const V& b) {
  const V ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

/// Max over points of `a` (vertices and 16 samples per segment) of the distance to polyline b.
template <typename V>
double directed_polyline_distance(const std::vector<V>& a, const std::vector<V>& b) {
  auto to_b = [&](const V& p) {
    double d = (p - b.front()).norm();
    for (size_t k = 0; k + 1 < b.size(); ++k)
      d = std::min(d, point_segment_distance(p, b[k], b[k + 1]));
    return d;
  };
  double worst = to_b(a.front());
  for (size_t k = 0; k + 1 < a.size(); ++k)
    for (int s = 1; s <= 16; ++s)
      worst = std::max(worst, to_b(V(a[k] + (a[k + 1] - a[k]) * (s / 16.0))));
  return worst;
}

/// Symmetric Hausdorff distance between two polylines (sampled).
template <typename V>
double polyline_distance(const std::vector<V>& a, const std::vector<V>& b) {
  return std::max(directed_polyline_distance(a, b), directed_polyline_distance(b, a));
}

/// Vertices of the strict convex hull by gift wrapping (independent of the library's monotone
/// chain), counter-clockwise, starting at the lowest-then-leftmost point.
inline std::vector<Eigen::Vector2d> gift_wrap_hull(const std::vector<Eigen::Vector2d>& pts) {
  auto cross = [](const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
    return u.x() * v.y() - u.y() * v.x();
  };
  size_t start = 0;
  for (size_t k = 1; k < pts.size(); ++k)
    if (pts[k].y() < pts[start].y() ||
        (pts[k].y() == pts[start].y() && pts[k].x() < pts[start].x()))
      start = k;
  std::vector<Eigen::Vector2d> hull;
  size_t cur = start;
  do {
    hull.push_back(pts[cur]);
    size_t next = cur == 0 ? 1 : 0;
    for (size_t k = 0; k < pts.size(); ++k) {
      if (k == cur) continue;
      const double c = cross(pts[next] - pts[cur], pts[k] - pts[cur]);
      // Clockwise-most candidate; on collinear ties the farthest (strict hull).
      if (c < 0.0 ||
          (c == 0.0 && (pts[k] - pts[cur]).squaredNorm() > (pts[next] - pts[cur]).squaredNorm()))
        next = k;
    }
    cur = next;
  } while (cur != start && hull.size() <= pts.size());
  return hull;
}

/// L-shaped prism as a soup of two boxes (6×2 cm and 2×6 cm in xy, 2 cm tall), corner at the
/// origin side: the L's outer corner is at (−0.03, −0.03).
inline Mesh make_l_shape_mesh() {
  Mesh m = make_box_mesh(Eigen::Vector3d(0.06, 0.02, 0.02));
  for (auto& v : m.vertices) v += Eigen::Vector3d(0.0, -0.02, 0.0);
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() = Eigen::Vector3d(-0.02, 0.0, 0.0);
  append_mesh(m, make_box_mesh(Eigen::Vector3d(0.02, 0.06, 0.02)), X);
  m.name = "l_shape";
  return m;
}

/// Closed 2-manifold after welding identical vertex positions: every edge in exactly two
/// triangles.
inline bool is_watertight(const Mesh& mesh) {
  std::map<std::array<double, 3>, int> weld;
  std::vector<int> id(mesh.vertices.size());
  for (size_t k = 0; k < mesh.vertices.size(); ++k) {
    const Eigen::Vector3d& v = mesh.vertices[k];
    id[k] =
        weld.emplace(std::array<double, 3>{v.x(), v.y(), v.z()}, int(weld.size())).first->second;
  }
  std::map<std::pair<int, int>, int> uses;
  for (const Eigen::Vector3i& t : mesh.triangles)
    for (int c = 0; c < 3; ++c) {
      const int a = id[t[c]], b = id[t[(c + 1) % 3]];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  for (const auto& [edge, n] : uses)
    if (n != 2) return false;
  return true;
}

/// Test shapes built from core/shapes.h: name and mesh.
inline std::vector<Mesh> test_shapes() {
  std::vector<Mesh> shapes;
  shapes.push_back(make_box_mesh(Eigen::Vector3d(0.05, 0.04, 0.08)));
  shapes.push_back(make_cylinder_mesh(0.03, 0.12, 48));
  shapes.push_back(make_sphere_mesh(0.035, 16, 32));
  shapes.push_back(make_torus_mesh(0.035, 0.012, 32, 16));
  shapes.push_back(make_l_shape_mesh());
  return shapes;
}

}  // namespace cordgrasp::test
