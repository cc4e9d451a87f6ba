#pragma once
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "cordgrasp/core/plane_cross_section.h"

namespace cordgrasp {

/// Tolerances of TIGHTEN (docs/algorithm.md §2.3).
struct TightenOptions {
  double eps_len_m = 1e-9;         ///< points closer than this to the anchor are not candidates
  double eps_area_m2 = 1e-16;      ///< eps_a: the ray does not rotate below this |cross|
                                   ///< (spec: 1e-14 · r²) [m²]
  double barycentric_tol = 1e-12;  ///< closed swept triangle: barycentric ≥ −tol [1]
  double dedup_m = 1e-7;           ///< consecutive output points closer than this merge [m]
};

/// Exact 2D TIGHTEN (docs/algorithm.md §2.3): wraps the guide polyline g0…gm taut around the
/// obstacle points V (candidates, typically V_S) by sweeping a ray from the current anchor to a
/// target moving along the guide; the first point swept joins the cord. `segments` (S) are only
/// used to FAIL when the ray does not rotate and the guide pierces the object. Returns the cord
/// from g0 to gm, or nullopt on FAIL (pierced guide, > 4|V|+8 points).
std::optional<std::vector<Eigen::Vector2d>> tighten_cord(const std::vector<Eigen::Vector2d>& guide,
                                                         const std::vector<Eigen::Vector2d>& points,
                                                         const std::vector<Segment2>& segments,
                                                         const TightenOptions& options = {});

}  // namespace cordgrasp
