#pragma once
// Private: the event search of TIGHTEN (docs/algorithm.md §2.3), shared by tighten_cord and
// front_cord.
#include <Eigen/Core>
#include <vector>

#include "plane_geometry_2d.h"

namespace cordgrasp::detail {

/// Index of the first point swept by the ray from `a` as its target moves from ga to gb
/// (docs/algorithm.md §2.3), or -1. `area` = cross(ga−a, gb−a), non-zero.
inline int first_swept_point(const Eigen::Vector2d& a, const Eigen::Vector2d& ga,
                             const Eigen::Vector2d& gb, double area,
                             const std::vector<Eigen::Vector2d>& points, double barycentric_tol,
                             double eps_len_m) {
  const double sgn = area > 0.0 ? 1.0 : -1.0;
  const double inv = 1.0 / area;
  const double tol = barycentric_tol;
  const double eps2 = eps_len_m * eps_len_m;
  int best = -1;
  Eigen::Vector2d best_d(0.0, 0.0);
  double best_d2 = 0.0;
  for (int k = 0; k < int(points.size()); ++k) {
    const Eigen::Vector2d& v = points[k];
    // Barycentric coordinates of v in (a, ga, gb).
    const double la = cross2(ga - v, gb - v) * inv;
    if (la < -tol) continue;
    const double lga = cross2(gb - v, a - v) * inv;
    if (lga < -tol) continue;
    const double lgb = cross2(a - v, ga - v) * inv;
    if (lgb < -tol) continue;
    const Eigen::Vector2d d = v - a;
    const double d2 = d.squaredNorm();
    if (d2 <= eps2) continue;
    if (best >= 0) {
      const double c = sgn * cross2(d, best_d);
      if (c < 0.0 || (c == 0.0 && d2 >= best_d2)) continue;
    }
    best = k;
    best_d = d;
    best_d2 = d2;
  }
  return best;
}

}  // namespace cordgrasp::detail
