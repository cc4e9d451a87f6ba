#pragma once
// Private: Andrew's monotone chain convex hull in 2D, with an Akl–Toussaint throw-away step for
// large inputs.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <vector>

#include "plane_geometry_2d.h"

namespace cordgrasp::detail {

/// Strict convex hull (collinear and duplicate points dropped), counter-clockwise, starting at
/// the lexicographically smallest point. `pts` is sorted in place; `hull` is overwritten.
inline void convex_hull_ccw_all(std::vector<Eigen::Vector2d>& pts,
                                std::vector<Eigen::Vector2d>& hull) {
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

/// Inputs from this many points on are thinned before their sort (a dense scan's plane section
/// gives thousands of candidates, of which a few percent are on the hull).
constexpr size_t kThinHullFromPoints = 256;
/// Every this-many-th point forms the subsample whose hull does the thinning.
constexpr size_t kThinHullStride = 8;
/// A point is dropped only when each orientation test puts it inside by this much, relative to
/// the squared coordinate magnitude: some 300 times the rounding bound of those tests.
constexpr double kThinHullMarginRel = 1e-12;

/// Akl–Toussaint throw-away: removes from `pts` the points strictly inside the hull `poly` of
/// some of them (each test decided by a margin far above rounding). Those points are interior
/// to the hull of `pts`, so they are no vertex of it. `poly`: strict, counter-clockwise.
inline void drop_points_inside_hull_of_some(std::vector<Eigen::Vector2d>& pts,
                                            const std::vector<Eigen::Vector2d>& poly) {
  const size_t m = poly.size();
  if (m < 3) return;
  Eigen::Vector2d lo = poly[0], hi = poly[0];
  for (const Eigen::Vector2d& v : poly) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const double s = std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff());
  const double margin = kThinHullMarginRel * s * s;
  const Eigen::Vector2d v0 = poly[0];
  // Fan from v0: a point strictly inside the wedge between spokes v0→poly[a] and
  // v0→poly[a + 1] is strictly inside the polygon iff it is strictly inside edge a. Neighbouring
  // points (a plane section's, along its segments) mostly share a wedge: the previous point's
  // and its two neighbours are tried first, else it is found by bisection.
  size_t a = 1;
  auto in_wedge = [&](size_t k, const Eigen::Vector2d& d) {
    return cross2(poly[k] - v0, d) > margin && cross2(d, poly[k + 1] - v0) > margin;
  };
  auto inside = [&](const Eigen::Vector2d& p) {
    if (p.x() <= lo.x() || p.y() <= lo.y() || p.x() >= hi.x() || p.y() >= hi.y()) return false;
    const Eigen::Vector2d d = p - v0;
    if (in_wedge(a, d)) {
    } else if (a + 2 < m && in_wedge(a + 1, d)) {
      ++a;
    } else if (a > 1 && in_wedge(a - 1, d)) {
      --a;
    } else {
      size_t k = 1, b = m - 1;
      if (!(cross2(poly[k] - v0, d) > 0.0) || !(cross2(d, poly[b] - v0) > 0.0)) return false;
      while (b - k > 1) {
        const size_t mid = (k + b) / 2;
        if (cross2(poly[mid] - v0, d) >= 0.0)
          k = mid;
        else
          b = mid;
      }
      if (!in_wedge(k, d)) return false;  // on a spoke, within the margin
      a = k;
    }
    return cross2(poly[a + 1] - poly[a], p - poly[a]) > margin;
  };
  pts.erase(std::remove_if(pts.begin(), pts.end(), inside), pts.end());
}

/// convex_hull_ccw_all's hull; a large input is first thinned by the hull of every
/// kThinHullStride-th point (same hull, far fewer points to sort). `pts` is reordered and
/// may lose points; `scratch` is reused storage.
inline void convex_hull_ccw(std::vector<Eigen::Vector2d>& pts, std::vector<Eigen::Vector2d>& hull,
                            std::vector<Eigen::Vector2d>& scratch) {
  if (pts.size() >= kThinHullFromPoints) {
    scratch.clear();
    for (size_t i = 0; i < pts.size(); i += kThinHullStride) scratch.push_back(pts[i]);
    convex_hull_ccw_all(scratch, hull);
    drop_points_inside_hull_of_some(pts, hull);
  }
  convex_hull_ccw_all(pts, hull);
}

}  // namespace cordgrasp::detail
