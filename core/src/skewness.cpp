#include "cordgrasp/core/skewness.h"

#include <algorithm>
#include <cmath>

namespace cordgrasp {

double skewness_alpha_rad(const Eigen::Vector3d& palm_axis, const Eigen::Vector3d& principal_axis) {
  const double na = palm_axis.norm();
  const double nb = principal_axis.norm();
  if (na <= 0.0 || nb <= 0.0) return 0.0;
  // atan2 of |a×b| and a·b is accurate near 0 and π, unlike acos.
  const double delta =
      std::atan2(palm_axis.cross(principal_axis).norm(), palm_axis.dot(principal_axis));
  const double quarter = M_PI / 2.0;
  const double alpha = std::abs(delta - quarter * std::round(delta / quarter));
  return std::clamp(alpha, 0.0, M_PI / 4.0);
}

}  // namespace cordgrasp
