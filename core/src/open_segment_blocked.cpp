#include "cordgrasp/core/open_segment_blocked.h"

#include <algorithm>
#include <cmath>

namespace cordgrasp {
namespace {
inline double cross2(const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
  return u.x() * v.y() - u.y() * v.x();
}
}  // namespace

bool open_segment_blocked(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                          const std::vector<Segment2>& segments, double eps_len_m) {
  const Eigen::Vector2d r = b - a;
  const double len2 = r.squaredNorm();
  const double len = std::sqrt(len2);
  if (len <= 2.0 * eps_len_m) return false;
  const double t_lo = eps_len_m / len, t_hi = 1.0 - eps_len_m / len;
  // Bounding box of (a, b) for a cheap reject.
  const Eigen::Vector2d lo = a.cwiseMin(b), hi = a.cwiseMax(b);
  for (const Segment2& s : segments) {
    if (std::max(s.a.x(), s.b.x()) < lo.x() || std::min(s.a.x(), s.b.x()) > hi.x() ||
        std::max(s.a.y(), s.b.y()) < lo.y() || std::min(s.a.y(), s.b.y()) > hi.y())
      continue;
    const Eigen::Vector2d sv = s.b - s.a, qa = s.a - a;
    const double denom = cross2(r, sv);
    if (denom != 0.0) {
      const double t = cross2(qa, sv) / denom;
      const double u = cross2(qa, r) / denom;
      if (u < 0.0 || u > 1.0) continue;
      if (t > t_lo && t < t_hi) return true;
    } else {
      if (cross2(qa, r) != 0.0) continue;  // parallel, apart
      const double ta = qa.dot(r) / len2, tb = (s.b - a).dot(r) / len2;
      if (std::max(std::min(ta, tb), t_lo) < std::min(std::max(ta, tb), t_hi)) return true;
    }
  }
  return false;
}

}  // namespace cordgrasp
