#pragma once
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "cordgrasp/core/cord_object.h"
#include "cordgrasp/core/cord_params.h"
#include "cordgrasp/core/grasp_region.h"
#include "cordgrasp/core/guide_frame.h"
#include "cordgrasp/core/plane_cross_section.h"

namespace cordgrasp {

/// Front cord of one guide triangle (docs/algorithm.md §3), in the triangle's plane frame.
struct FrontCord {
  CordCase cord_case = CordCase::kI;
  PlaneFrame frame;                   ///< guide_frame(P1, P2, P3)
  std::vector<Eigen::Vector2d> cord;  ///< P_r = F0, P_ρ, …, P_λ, P_l = Fk (frame coords) [m]

  const Eigen::Vector2d& p_r() const { return cord.front(); }
  const Eigen::Vector2d& p_l() const { return cord.back(); }
  /// The cord as a 3D polyline [m].
  Polyline3 cord_3d() const;
};

/// Why front_cord() gave no cord.
enum class FrontCordFailure {
  kNone,
  kGuideBlocked,         ///< P1P2 or P1P3 meets the object (docs/algorithm.md §3)
  kNoContact,            ///< Case I: no cross-section inside the guide triangle
  kGraspPointsTooClose,  ///< ‖P_l − P_r‖ < min_grasp_gap_m (docs/algorithm.md §2.5)
  kTightenFailed,        ///< TIGHTEN failed (docs/algorithm.md §2.3)
  kTooFewSegments,       ///< Case II front cord with < 2 segments (docs/algorithm.md §3)
};

/// Front cord of guide triangle (P1, P2, P3) (docs/algorithm.md §3): Case II when P2P3 meets the
/// cross-section (P_l, P_r = its hits nearest P2, P3), else Case I (P_l, P_r = first and last
/// contacts of TIGHTEN on P1→P2→P3→P1); then TIGHTEN on P_r→P3→P1→P2→P_l. Works in the
/// cross-section of the plane (Primitive A on the BVH). The triangle must be non-degenerate.
std::optional<FrontCord> front_cord(const CordObject& object, const Eigen::Vector3d& p1,
                                    const Eigen::Vector3d& p2, const Eigen::Vector3d& p3,
                                    const CordParams& params = {},
                                    FrontCordFailure* failure = nullptr);

/// front_cord() from the cross-section segments of guide_frame(P1, P2, P3) (Primitive A; any
/// superset of the segments meeting the closed triangle gives the same result). `radius_m` is
/// the object's bounding radius r (sets TIGHTEN's eps_a).
std::optional<FrontCord> front_cord_from_segments(const PlaneFrame& frame,
                                                  const Eigen::Vector3d& p2,
                                                  const Eigen::Vector3d& p3,
                                                  const std::vector<Segment2>& segments,
                                                  double radius_m, const CordParams& params = {},
                                                  FrontCordFailure* failure = nullptr);

}  // namespace cordgrasp
