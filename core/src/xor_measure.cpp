#include "cordgrasp/core/xor_measure.h"

#include <stdexcept>

#include "cordgrasp/core/xor_area.h"

namespace cordgrasp {
namespace {

std::vector<Eigen::Vector2d> project(const Polyline3& cord, const PlaneFrame& frame) {
  std::vector<Eigen::Vector2d> q;
  q.reserve(cord.size());
  for (const Eigen::Vector3d& x : cord) q.push_back(frame.to_2d(x));
  return q;  // closing edge P_l → P_r is implicit
}

}  // namespace

double xor_measure(const std::vector<Polyline3>& front_cords, const PlaneFrame& seed_frame,
                   const CordParams& params) {
  const size_t count = front_cords.size();
  if (count < 3 || count % 2 == 0)
    throw std::invalid_argument("xor_measure: need 2n+1 front cords with n >= 1");
  const size_t n = count / 2;
  const std::vector<Eigen::Vector2d> q0 = project(front_cords[n], seed_frame);
  double sum = 0.0;
  for (size_t i = 0; i < count; ++i) {
    if (i == n) continue;
    const std::vector<Eigen::Vector2d> qi = project(front_cords[i], seed_frame);
    sum += params.xor_backend == XorBackend::kConvex
               ? convex_xor_area(q0, qi)
               : xor_area(q0, qi, params.clipper_scale);
  }
  return sum / double(2 * n);
}

}  // namespace cordgrasp
