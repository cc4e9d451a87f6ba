#pragma once
#include <Eigen/Core>
#include <vector>

namespace cordgrasp {

/// Area of a simple polygon (absolute shoelace) [m²].
double polygon_area(const std::vector<Eigen::Vector2d>& polygon);

/// A(P ⊕ Q) with Clipper 6.4.2 (docs/algorithm.md §6): coordinates scaled by `scale` and rounded,
/// AddPath(P, subject), AddPath(Q, clip), Execute(ctXor, NonZero, NonZero), Σ Area / S².
/// A polygon with < 3 vertices or zero area gives the other's area [m²].
double xor_area(const std::vector<Eigen::Vector2d>& p, const std::vector<Eigen::Vector2d>& q,
                double scale = 1e7);

/// A(P ∩ Q) with Clipper 6.4.2 (ctIntersection), same scaling as xor_area [m²].
double intersection_area(const std::vector<Eigen::Vector2d>& p,
                         const std::vector<Eigen::Vector2d>& q, double scale = 1e7);

/// A(P) + A(Q) − 2·A(P ∩ Q) with P ∩ Q by exact convex clipping, in double precision; both
/// polygons must be convex (either orientation) [m²].
double convex_xor_area(const std::vector<Eigen::Vector2d>& p,
                       const std::vector<Eigen::Vector2d>& q);

}  // namespace cordgrasp
