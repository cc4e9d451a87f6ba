#pragma once
#include <Eigen/Core>
#include <vector>

#include "cordgrasp/core/plane_cross_section.h"

namespace cordgrasp {

/// True when some cross-section segment meets segment (a, b) at a point farther than
/// `eps_len_m` from both a and b (spec §2.4 "guide pierces object", §3.1 "must be free").
/// Collinear overlaps count. Endpoint contacts within eps_len_m do not.
bool open_segment_blocked(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                          const std::vector<Segment2>& segments, double eps_len_m = 1e-9);

}  // namespace cordgrasp
