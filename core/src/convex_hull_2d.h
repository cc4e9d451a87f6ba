#pragma once
// Private: Andrew's monotone chain convex hull in 2D.
#include <Eigen/Core>
#include <algorithm>
#include <vector>

#include "plane_geometry_2d.h"

namespace cordgrasp::detail {

/// Strict convex hull (collinear and duplicate points dropped), counter-clockwise, starting at
/// the lexicographically smallest point. `pts` is sorted in place; `hull` is overwritten.
inline void convex_hull_ccw(std::vector<Eigen::Vector2d>& pts, std::vector<Eigen::Vector2d>& hull) {
  std::sort(pts.begin(), pts.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  const size_t n = pts.size();
  hull.resize(2 * n + 1);
  if (n < 3) {
    hull.assign(pts.begin(), pts.end());
    if (n == 2 && pts[0] == pts[1]) hull.resize(1);
    return;
  }
  size_t k = 0;
  for (size_t i = 0; i < n; ++i) {
    while (k >= 2 && cross2(hull[k - 1] - hull[k - 2], pts[i] - hull[k - 2]) <= 0.0) --k;
    hull[k++] = pts[i];
  }
  for (size_t i = n - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross2(hull[k - 1] - hull[k - 2], pts[i] - hull[k - 2]) <= 0.0) --k;
    hull[k++] = pts[i];
  }
  hull.resize(k > 1 ? k - 1 : k);
}

}  // namespace cordgrasp::detail
