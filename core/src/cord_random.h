#pragma once
// Private, portable random helpers on std::mt19937_64: the standard distributions are
// implementation-defined, these give identical sequences with every standard library.
#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace cordgrasp::detail {

/// Uniform integer in [0, n), n ≥ 1 (rejection sampling, unbiased).
inline std::uint64_t uniform_index(std::mt19937_64& rng, std::uint64_t n) {
  const std::uint64_t limit = ~std::uint64_t(0) - (~std::uint64_t(0) % n);
  for (;;) {
    const std::uint64_t x = rng();
    if (x < limit) return x % n;
  }
}

/// Uniform double in [0, 1) with 53 random bits.
inline double uniform01(std::mt19937_64& rng) { return double(rng() >> 11) * 0x1.0p-53; }

/// Fisher–Yates shuffle.
template <typename T>
void shuffle(std::vector<T>& v, std::mt19937_64& rng) {
  for (size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[uniform_index(rng, i)]);
}

/// Uniform unit vector.
inline Eigen::Vector3d uniform_unit_vector(std::mt19937_64& rng) {
  const double z = 2.0 * uniform01(rng) - 1.0;
  const double phi = 2.0 * 3.14159265358979323846 * uniform01(rng);
  const double rho = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {rho * std::cos(phi), rho * std::sin(phi), z};
}

/// Uniform point in the ball of radius `radius` (rejection from the cube).
inline Eigen::Vector3d uniform_in_ball(std::mt19937_64& rng, double radius) {
  for (;;) {
    const Eigen::Vector3d p(2.0 * uniform01(rng) - 1.0, 2.0 * uniform01(rng) - 1.0,
                            2.0 * uniform01(rng) - 1.0);
    if (p.squaredNorm() <= 1.0) return radius * p;
  }
}

}  // namespace cordgrasp::detail
