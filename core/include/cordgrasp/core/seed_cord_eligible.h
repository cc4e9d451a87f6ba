#pragma once
#include <Eigen/Core>
#include <vector>

#include "cordgrasp/core/cord_params.h"
#include "cordgrasp/core/front_cord.h"

namespace cordgrasp {

/// ξ = max over cord vertices of ‖F_k − P_m‖, P_m = (P_l + P_r)/2 (docs/algorithm.md §1) [m].
/// `cord` runs from P_r to P_l; it must not be empty.
double cord_xi(const std::vector<Eigen::Vector2d>& cord);

/// Case II angle test (docs/algorithm.md §3): when the rays P_l + s(P_λ−P_l) and P_r + t(P_ρ−P_r),
/// s, t ≥ 0, intersect, angle(P_l−P_λ, P_r−P_ρ) must be ≤ max_angle_rad. Parallel or
/// diverging rays, and cords with one segment, pass.
bool passes_squeeze_test(const std::vector<Eigen::Vector2d>& cord, double max_angle_rad);

/// Eligibility of a seed front cord (docs/algorithm.md §3): ξ_min ≤ ξ ≤ ξ_max, and the angle test
/// in Case II.
bool seed_cord_eligible(const FrontCord& front, const CordParams& params = {});

}  // namespace cordgrasp
