#include "cordgrasp/core/seed_cord_eligible.h"

#include <algorithm>
#include <cmath>

#include "plane_geometry_2d.h"

namespace cordgrasp {

using detail::cross2;

double cord_xi(const std::vector<Eigen::Vector2d>& cord) {
  const Eigen::Vector2d p_m = 0.5 * (cord.front() + cord.back());
  double xi2 = 0.0;
  for (const Eigen::Vector2d& f : cord) xi2 = std::max(xi2, (f - p_m).squaredNorm());
  return std::sqrt(xi2);
}

bool passes_squeeze_test(const std::vector<Eigen::Vector2d>& cord, double max_angle_rad) {
  if (cord.size() < 3) return true;
  const Eigen::Vector2d& p_r = cord.front();
  const Eigen::Vector2d& p_rho = cord[1];
  const Eigen::Vector2d& p_l = cord.back();
  const Eigen::Vector2d& p_lambda = cord[cord.size() - 2];
  const Eigen::Vector2d u = p_l - p_lambda, w = p_r - p_rho;
  // P_l − s·u = P_r − t·w  ⇔  s·(−u) + t·w = P_r − P_l.
  const double det = cross2(-u, w);
  if (std::abs(det) <= 1e-12 * u.norm() * w.norm()) return true;  // parallel rays
  const Eigen::Vector2d rhs = p_r - p_l;
  const double s = cross2(rhs, w) / det;
  const double t = cross2(-u, rhs) / det;
  if (s < 0.0 || t < 0.0) return true;  // diverging rays
  const double angle = std::atan2(std::abs(cross2(u, w)), u.dot(w));
  return angle <= max_angle_rad;
}

bool seed_cord_eligible(const FrontCord& front, const CordParams& params) {
  const double xi = cord_xi(front.cord);
  if (xi < params.xi_min_m || xi > params.xi_max_m) return false;
  if (front.cord_case == CordCase::kII &&
      !passes_squeeze_test(front.cord, params.max_squeeze_angle_rad))
    return false;
  return true;
}

}  // namespace cordgrasp
