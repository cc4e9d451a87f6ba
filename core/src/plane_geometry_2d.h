#pragma once
// Private 2D helpers of the cord code.
#include <Eigen/Core>

namespace cordgrasp::detail {

inline double cross2(const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
  return u.x() * v.y() - u.y() * v.x();
}

/// Shoelace area, positive for counter-clockwise polygons [m²].
template <typename Points>
double signed_polygon_area(const Points& p) {
  double a = 0.0;
  const size_t n = p.size();
  for (size_t k = 0; k < n; ++k) a += cross2(p[k], p[(k + 1) % n]);
  return 0.5 * a;
}

}  // namespace cordgrasp::detail
