#include "cordgrasp/core/sphere_points.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace cordgrasp {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// Lindemann–LaValle incremental 2D lattice point i ≥ 1, in [0, 1)².
Eigen::Vector2d lattice_point(long long i) {
  static const double kL[4][2] = {{0.0, 0.0}, {0.5, 0.5}, {0.5, 0.0}, {0.0, 0.5}};
  Eigen::Vector2d p(0.0, 0.0);
  double factor = 1.0;
  for (;;) {
    const int digit = int(i % 4);
    p.x() += factor * kL[digit][0];
    p.y() += factor * kL[digit][1];
    i /= 4;
    if (i == 0) return p;
    factor *= 0.5;
  }
}

/// Spherical linear interpolation between unit vectors a and b.
Eigen::Vector3d slerp(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double s) {
  const double theta = std::acos(std::clamp(a.dot(b), -1.0, 1.0));
  const double sin_t = std::sin(theta);
  if (sin_t < 1e-15) return a;
  return (std::sin((1.0 - s) * theta) / sin_t) * a + (std::sin(s * theta) / sin_t) * b;
}

/// Cube faces as corner quadruples (c00, c10, c01, c11): slerp c00→c10 and c01→c11 at u,
/// then between the two results at v. Corners are unit vectors to (±1, ±1, ±1).
std::array<std::array<Eigen::Vector3d, 4>, 6> cube_faces() {
  auto c = [](double x, double y, double z) { return Eigen::Vector3d(x, y, z).normalized(); };
  return {{
      {c(1, -1, -1), c(1, 1, -1), c(1, -1, 1), c(1, 1, 1)},      // +x
      {c(1, 1, 1), c(-1, 1, 1), c(1, 1, -1), c(-1, 1, -1)},      // +y
      {c(-1, -1, -1), c(1, -1, -1), c(-1, 1, -1), c(1, 1, -1)},  // −z
      {c(-1, 1, 1), c(-1, 1, -1), c(-1, -1, 1), c(-1, -1, -1)},  // −x
      {c(-1, -1, 1), c(1, -1, 1), c(-1, -1, -1), c(1, -1, -1)},  // −y
      {c(1, 1, 1), c(1, -1, 1), c(-1, 1, 1), c(-1, -1, 1)},      // +z
  }};
}

}  // namespace

std::vector<Eigen::Vector3d> sphere_points(int count, SphereSequence kind) {
  if (count < 0) throw std::invalid_argument("sphere_points: negative count");
  std::vector<Eigen::Vector3d> out;
  out.reserve(count);
  if (kind == SphereSequence::kFibonacci) {
    const double golden = kPi * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < count; ++i) {
      const double z = 1.0 - (2.0 * i + 1.0) / count;
      const double rho = std::sqrt(std::max(0.0, 1.0 - z * z));
      const double phi = golden * i;
      out.emplace_back(rho * std::cos(phi), rho * std::sin(phi), z);
    }
    return out;
  }
  const auto faces = cube_faces();
  for (long long i = 1; int(out.size()) < count; ++i) {
    const Eigen::Vector2d uv = lattice_point(i);
    for (const auto& f : faces) {
      if (int(out.size()) >= count) break;
      const Eigen::Vector3d a = slerp(f[0], f[1], uv.x());
      const Eigen::Vector3d b = slerp(f[2], f[3], uv.x());
      out.push_back(slerp(a.normalized(), b.normalized(), uv.y()).normalized());
    }
  }
  return out;
}

}  // namespace cordgrasp
