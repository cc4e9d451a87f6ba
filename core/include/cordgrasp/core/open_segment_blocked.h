#pragma once
#include <Eigen/Core>
#include <vector>

#include "cordgrasp/core/plane_cross_section.h"

namespace cordgrasp {

/// True when some cross-section segment crosses segment (a, b) ("guide pierces the object", "must
/// be free"; docs/algorithm.md §2.3, §3): its endpoints lie strictly on opposite sides of the
/// line, farther than `eps_len_m` from it, and the crossing is farther than eps_len_m from a and
/// b. Touching the line or running along it (grazing the surface) does not count.
bool open_segment_blocked(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                          const std::vector<Segment2>& segments, double eps_len_m = 1e-9);

}  // namespace cordgrasp
