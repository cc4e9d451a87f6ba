#pragma once
// Private: A(P ⊕ Q) of two convex polygons by Sutherland–Hodgman clipping (the kConvex χ backend).
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <vector>

namespace cordgrasp::detail {

/// Signed shoelace area of n points (positive counter-clockwise) [m²].
inline double signed_area(const Eigen::Vector2d* p, size_t n) {
  double a = 0.0;
  for (size_t k = 0, j = n - 1; k < n; j = k++) a += p[j].x() * p[k].y() - p[j].y() * p[k].x();
  return 0.5 * a;
}

/// A(P ∩ Q) for convex Q (either orientation), P any simple polygon, n, m ≥ 3 [m²].
inline double convex_intersection_area(const Eigen::Vector2d* p, size_t n, const Eigen::Vector2d* q,
                                       size_t m, double q_signed_area) {
  struct Pt {
    double x, y;
  };
  thread_local std::vector<Pt> buf_a, buf_b;
  buf_a.resize(n + m + 2);
  buf_b.resize(n + m + 2);
  Pt* cur = buf_a.data();
  Pt* out = buf_b.data();
  for (size_t i = 0; i < n; ++i) cur[i] = {p[i].x(), p[i].y()};
  size_t count = n;
  const bool ccw = q_signed_area > 0.0;
  for (size_t k = 0; k < m && count > 0; ++k) {
    const Eigen::Vector2d& a = ccw ? q[k] : q[m - 1 - k];
    const Eigen::Vector2d& b = ccw ? q[(k + 1) % m] : q[(2 * m - 2 - k) % m];
    const double ax = a.x(), ay = a.y(), ex = b.x() - ax, ey = b.y() - ay;
    size_t kept = 0;
    Pt prev = cur[count - 1];
    double d_prev = ex * (prev.y - ay) - ey * (prev.x - ax);
    for (size_t i = 0; i < count; ++i) {
      const Pt c = cur[i];
      const double d_c = ex * (c.y - ay) - ey * (c.x - ax);
      if ((d_c >= 0.0) != (d_prev >= 0.0)) {
        const double t = d_prev / (d_prev - d_c);
        out[kept++] = {prev.x + (c.x - prev.x) * t, prev.y + (c.y - prev.y) * t};
      }
      if (d_c >= 0.0) out[kept++] = c;
      prev = c;
      d_prev = d_c;
    }
    std::swap(cur, out);
    count = kept;
  }
  if (count < 3) return 0.0;
  double area = 0.0;
  for (size_t k = 0, j = count - 1; k < count; j = k++)
    area += cur[j].x * cur[k].y - cur[j].y * cur[k].x;
  return 0.5 * std::abs(area);
}

/// A(P) + A(Q) − 2·A(P ∩ Q) for convex P, Q; a polygon with < 3 points or zero area counts as
/// empty [m²].
inline double convex_xor_area(const Eigen::Vector2d* p, size_t n, const Eigen::Vector2d* q,
                              size_t m) {
  const double sp = n >= 3 ? signed_area(p, n) : 0.0;
  const double sq = m >= 3 ? signed_area(q, m) : 0.0;
  if (sp == 0.0 || sq == 0.0) return std::abs(sp) + std::abs(sq);
  const double inter = convex_intersection_area(p, n, q, m, sq);
  return std::max(0.0, std::abs(sp) + std::abs(sq) - 2.0 * inter);
}

}  // namespace cordgrasp::detail
