#include "cordgrasp/core/tighten_cord.h"

#include <algorithm>
#include <cmath>

#include "cordgrasp/core/open_segment_blocked.h"
#include "first_swept_point.h"

namespace cordgrasp {
namespace {

inline double cross2(const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
  return u.x() * v.y() - u.y() * v.x();
}

}  // namespace

std::optional<std::vector<Eigen::Vector2d>> tighten_cord(const std::vector<Eigen::Vector2d>& guide,
                                                         const std::vector<Eigen::Vector2d>& points,
                                                         const std::vector<Segment2>& segments,
                                                         const TightenOptions& opt) {
  if (guide.empty()) return std::nullopt;
  const size_t cap = 4 * points.size() + 8;
  std::vector<Eigen::Vector2d> cord{guide.front()};
  Eigen::Vector2d a = guide.front();
  for (size_t k = 0; k + 1 < guide.size(); ++k) {
    Eigen::Vector2d ga = guide[k];
    const Eigen::Vector2d gb = guide[k + 1];
    for (;;) {
      const double area = cross2(ga - a, gb - a);
      if (std::abs(area) <= opt.eps_area_m2) {
        if (open_segment_blocked(a, gb, segments, opt.eps_len_m)) return std::nullopt;
        break;
      }
      const int best =
          detail::first_swept_point(a, ga, gb, area, points, opt.barycentric_tol, opt.eps_len_m);
      if (best < 0) break;
      const Eigen::Vector2d v = points[best];
      cord.push_back(v);
      if (cord.size() > cap) return std::nullopt;
      // Where the target is at the event: line(a, v) ∩ segment [ga, gb].
      const Eigen::Vector2d d = v - a;
      const double den = cross2(d, gb - ga);
      if (den != 0.0) {
        const double s = std::clamp(-cross2(d, ga - a) / den, 0.0, 1.0);
        ga = ga + s * (gb - ga);
      }
      a = v;
    }
  }
  cord.push_back(guide.back());
  std::vector<Eigen::Vector2d> out;
  out.reserve(cord.size());
  const double dedup2 = opt.dedup_m * opt.dedup_m;
  for (const Eigen::Vector2d& p : cord)
    if (out.empty() || (p - out.back()).squaredNorm() >= dedup2) out.push_back(p);
  // The cord ends exactly at gm, even when an event point within dedup_m replaced it.
  if (out.size() > 1) out.back() = guide.back();
  return out;
}

}  // namespace cordgrasp
