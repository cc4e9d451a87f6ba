#pragma once
#include <Eigen/Core>
#include <optional>

#include "cordgrasp/core/cord_object.h"
#include "cordgrasp/core/cord_params.h"
#include "cordgrasp/core/grasp_region.h"

namespace cordgrasp {

/// Why scan_cord_set() gave no region.
enum class ScanFailure {
  kNone,
  kSeedCord,     ///< the seed front cord failed (docs/algorithm.md §3)
  kNotEligible,  ///< the seed cord failed ξ bounds or the angle test (docs/algorithm.md §3)
  kSideCord,     ///< a rotated cord T^{±i} failed or changed case (docs/algorithm.md §4)
};

/// Number of cords per side n = max(1, round(W_palm / (2θd))) with d the radius at which
/// segment P2P3 moves (docs/algorithm.md §4), capped at params.max_cords_per_side.
int cords_per_side(const Eigen::Vector3d& p1, const Eigen::Vector3d& p2, const Eigen::Vector3d& p3,
                   const Eigen::Vector3d& p_m, double palm_width_m, const CordParams& params = {});

/// A full set for seed guide triangle T0 = (P1, P2, P3) (docs/algorithm.md §3–§6): eligible seed
/// front cord, the 2n rotated guide triangles Rot(P1, a, ±iθ)·T0 with a = unit(ν × (P_m − P1)),
/// each in the seed's case, and χ. Every GraspRegion field is filled (from_local_improvement
/// false); under SideCordPolicy::kEmptyWhenMissed a cord that missed the object is an empty
/// polyline.
std::optional<GraspRegion> scan_cord_set(const CordObject& object, const Eigen::Vector3d& p1,
                                         const Eigen::Vector3d& p2, const Eigen::Vector3d& p3,
                                         double palm_width_m, const CordParams& params = {},
                                         ScanFailure* failure = nullptr);

}  // namespace cordgrasp
