#pragma once
#include <Eigen/Core>

namespace cordgrasp {

/// Orthonormal frame of a guide plane Π (docs/algorithm.md §1): origin, in-plane axes e1, e2,
/// normal ν.
struct PlaneFrame {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< [m]
  Eigen::Vector3d e1 = Eigen::Vector3d::UnitX();
  Eigen::Vector3d e2 = Eigen::Vector3d::UnitY();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< ν = e1 × e2

  /// In-plane coordinates (e1·(X−O), e2·(X−O)) of a 3D point (orthogonal projection) [m].
  Eigen::Vector2d to_2d(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d d = p - origin;
    return {e1.dot(d), e2.dot(d)};
  }
  /// 3D point of in-plane coordinates [m].
  Eigen::Vector3d to_3d(const Eigen::Vector2d& q) const { return origin + q.x() * e1 + q.y() * e2; }
};

/// Frame of guide triangle T = (P1, P2, P3) (docs/algorithm.md §1): origin P1, e1 = unit(P2−P1),
/// ν = unit((P2−P1)×(P3−P1)), e2 = ν×e1. In it T is counter-clockwise.
/// The triangle must be non-degenerate.
PlaneFrame guide_frame(const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                       const Eigen::Vector3d& p3);

/// Acute test of Algorithm 1 (docs/algorithm.md §5): all three (Pb−Pa)·(Pc−Pa) > 0 and area >
/// min_area_m2.
bool is_acute_triangle(const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                       const Eigen::Vector3d& p3, double min_area_m2 = 1e-12);

}  // namespace cordgrasp
