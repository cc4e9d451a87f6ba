#pragma once
// Private: the "guide pierces the object" predicate of TIGHTEN (docs/algorithm.md §2.3), shared by
// open_segment_blocked and front_cord.
#include <Eigen/Core>
#include <cmath>

#include "cordgrasp/core/plane_cross_section.h"

namespace cordgrasp::detail {

/// True when cross-section segment s crosses the open segment (a, b): its endpoints lie
/// strictly on opposite sides of line ab (farther than eps from it) and the crossing is
/// farther than eps from a and from b. Segments touching or running along the line
/// (grazing the surface, e.g. a cord segment lying on a flat face) do not pierce.
/// `dir` = (b − a)/len.
inline bool segment_pierces(const Eigen::Vector2d& a, const Eigen::Vector2d& dir, double len,
                            const Segment2& s, double eps) {
  const Eigen::Vector2d pa = s.a - a, pb = s.b - a;
  const double da = dir.x() * pa.y() - dir.y() * pa.x();
  const double db = dir.x() * pb.y() - dir.y() * pb.x();
  if (!((da > eps && db < -eps) || (da < -eps && db > eps))) return false;
  const double along = dir.dot(pa + (pb - pa) * (da / (da - db)));
  return along > eps && along < len - eps;
}

}  // namespace cordgrasp::detail
