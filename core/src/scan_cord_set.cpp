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

int cords_per_side(const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                   const Eigen::Vector3d& p3, const Eigen::Vector3d& p_m, double palm_width_m,
                   const CordParams& params) {
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
  // A set is valid only if every ±i cord is; the outermost ones fail most often, so they are
  // built first (same result, less work). The shrinking variant needs increasing i.
  std::vector<Polyline3> upper(n), lower(n);  // index i − 1
  const bool outermost_first = !params.shrink_on_failure;
  for (int step = 0; step < n; ++step) {
    const int i = outermost_first ? n - step : step + 1;
    bool ok = true;
    for (int side : {+1, -1}) {
      const Eigen::AngleAxisd rot(side * i * params.scan_angle_rad, axis);
      const Eigen::Vector3d q2 = p1 + rot * (p2 - p1), q3 = p1 + rot * (p3 - p1);
      const std::optional<FrontCord> fc = front_cord(object, p1, q2, q3, params);
      if (!fc || fc->cord_case != seed->cord_case) {
        ok = false;
        break;
      }
      (side > 0 ? upper : lower)[i - 1] = fc->cord_3d();
    }
    if (!ok) {
      if (outermost_first || i == 1) return fail(ScanFailure::kSideCord, failure);
      n = i - 1;  // symmetric shrinking (spec §11.6 flag)
      upper.resize(n);
      lower.resize(n);
      break;
    }
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
