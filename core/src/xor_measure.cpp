#include "cordgrasp/core/xor_measure.h"

#include <stdexcept>

#include "convex_xor_area.h"
#include "cordgrasp/core/xor_area.h"

namespace cordgrasp {
namespace {

void project(const Polyline3& cord, const PlaneFrame& frame, std::vector<Eigen::Vector2d>& q) {
  q.clear();
  for (const Eigen::Vector3d& x : cord) q.push_back(frame.to_2d(x));  // P_l→P_r implicit
}

}  // namespace

double xor_measure(const std::vector<Polyline3>& front_cords, const PlaneFrame& seed_frame,
                   const CordParams& params) {
  const size_t count = front_cords.size();
  if (count < 3 || count % 2 == 0)
    throw std::invalid_argument("xor_measure: need 2n+1 front cords with n >= 1");
  const size_t n = count / 2;
  thread_local std::vector<Eigen::Vector2d> q0, qi;
  project(front_cords[n], seed_frame, q0);
  double sum = 0.0;
  for (size_t i = 0; i < count; ++i) {
    if (i == n) continue;
    project(front_cords[i], seed_frame, qi);
    sum += params.xor_backend == XorBackend::kConvex
               ? detail::convex_xor_area(q0.data(), q0.size(), qi.data(), qi.size())
               : xor_area(q0, qi, params.clipper_scale);
  }
  return sum / double(2 * n);
}

}  // namespace cordgrasp
