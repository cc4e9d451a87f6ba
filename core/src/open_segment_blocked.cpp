#include "cordgrasp/core/open_segment_blocked.h"

#include <algorithm>
#include <cmath>

#include "segment_pierces.h"

namespace cordgrasp {

bool open_segment_blocked(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                          const std::vector<Segment2>& segments, double eps_len_m) {
  const double len = (b - a).norm();
  if (len <= 2.0 * eps_len_m) return false;
  const Eigen::Vector2d dir = (b - a) / len;
  for (const Segment2& s : segments)
    if (detail::segment_pierces(a, dir, len, s, eps_len_m)) return true;
  return false;
}

}  // namespace cordgrasp
