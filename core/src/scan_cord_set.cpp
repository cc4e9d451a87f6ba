#include "cordgrasp/core/scan_cord_set.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "cordgrasp/core/front_cord.h"
#include "cordgrasp/core/seed_cord_eligible.h"
#include "cordgrasp/core/xor_measure.h"

namespace cordgrasp {
namespace {

std::optional<GraspRegion> fail(ScanFailure why, ScanFailure* out) {
  if (out) *out = why;
  return std::nullopt;
}

}  // namespace

int cords_per_side(const Eigen::Vector3d& p1, const Eigen::Vector3d& p2, const Eigen::Vector3d& p3,
                   const Eigen::Vector3d& p_m, double palm_width_m, const CordParams& params) {
  const Eigen::Vector3d v = (p_m - p1).normalized();
  const double d = std::abs((0.5 * (p2 + p3) - p1).dot(v));
  const double n = std::round(palm_width_m / (2.0 * params.scan_angle_rad * d));
  if (!(n >= 1.0)) return 1;  // also catches NaN from d = 0
  return int(std::min<double>(n, std::max(1, params.max_cords_per_side)));
}

std::optional<GraspRegion> scan_cord_set(const CordObject& object, const Eigen::Vector3d& p1,
                                         const Eigen::Vector3d& p2, const Eigen::Vector3d& p3,
                                         double palm_width_m, const CordParams& params,
                                         ScanFailure* failure) {
  if (failure) *failure = ScanFailure::kNone;
  const std::optional<FrontCord> seed = front_cord(object, p1, p2, p3, params);
  if (!seed) return fail(ScanFailure::kSeedCord, failure);
  if (!seed_cord_eligible(*seed, params)) return fail(ScanFailure::kNotEligible, failure);

  GraspRegion region;
  region.p1 = p1;
  region.p2 = p2;
  region.p3 = p3;
  region.normal = seed->frame.normal;
  region.cord_case = seed->cord_case;
  region.p_l = seed->frame.to_3d(seed->p_l());
  region.p_r = seed->frame.to_3d(seed->p_r());
  region.p_m = 0.5 * (region.p_l + region.p_r);
  region.xi_m = cord_xi(seed->cord);

  const Eigen::Vector3d axis = region.normal.cross(region.p_m - p1).normalized();
  int n = cords_per_side(p1, p2, p3, region.p_m, palm_width_m, params);
  std::vector<Polyline3> upper(n), lower(n);  // index i − 1
  auto rotated = [&](int i, int side, Eigen::Vector3d& q2, Eigen::Vector3d& q3) {
    const Eigen::AngleAxisd rot(side * i * params.scan_angle_rad, axis);
    q2 = p1 + rot * (p2 - p1);
    q3 = p1 + rot * (p3 - p1);
  };
  // Builds the ±i cord; false when the set must be discarded (or shrunk).
  auto build = [&](int i, int side) {
    Eigen::Vector3d q2, q3;
    rotated(i, side, q2, q3);
    FrontCordFailure why = FrontCordFailure::kNone;
    const std::optional<FrontCord> fc = front_cord(object, p1, q2, q3, params, &why);
    Polyline3& slot = (side > 0 ? upper : lower)[i - 1];
    if (fc && fc->cord_case == seed->cord_case) {
      slot = fc->cord_3d();
      return true;
    }
    if (!fc && why == FrontCordFailure::kNoContact &&
        (params.side_cord_policy == SideCordPolicy::kEmptyWhenMissed ||
         params.side_cord_policy == SideCordPolicy::kFallback)) {
      slot.clear();  // empty Q_i: χ counts A(Q_0) for it (docs/algorithm.md §6 degenerate rule)
      return true;
    }
    return false;
  };
  if (params.side_cord_policy == SideCordPolicy::kShrink) {
    // kShrink: increasing i; the first failing ±i shrinks n to i − 1 (n ≥ 1 required).
    for (int i = 1; i <= n; ++i) {
      if (build(i, +1) && build(i, -1)) continue;
      if (i == 1) return fail(ScanFailure::kSideCord, failure);
      n = i - 1;
      upper.resize(n);
      lower.resize(n);
      break;
    }
  } else {
    // A set is valid only if every ±i cord is; the outermost cords fail most often, so they
    // are built first (same result, less work).
    for (int i = n; i >= 1; --i)
      for (int side : {+1, -1})
        if (!build(i, side)) return fail(ScanFailure::kSideCord, failure);
  }
  region.n = n;
  region.front_cords.reserve(2 * n + 1);
  for (int i = n; i >= 1; --i) region.front_cords.push_back(std::move(lower[i - 1]));
  region.front_cords.push_back(seed->cord_3d());
  for (int i = 1; i <= n; ++i) region.front_cords.push_back(std::move(upper[i - 1]));
  region.chi_m2 = xor_measure(region.front_cords, seed->frame, params);
  return region;
}

}  // namespace cordgrasp
