#include "cordgrasp/core/wilson_interval.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cordgrasp {

ProportionInterval wilson_interval(int k, int n, double z) {
  if (n < 0 || k < 0 || k > n || !(z > 0.0) || !std::isfinite(z))
    throw std::invalid_argument("wilson_interval: need 0 <= k <= n and z > 0, got k " +
                                std::to_string(k) + ", n " + std::to_string(n));
  ProportionInterval out;
  if (n == 0) return out;
  const double nn = n, p = k / nn, z2 = z * z;
  const double centre = (p + z2 / (2.0 * nn)) / (1.0 + z2 / nn);
  const double half = z / (1.0 + z2 / nn) * std::sqrt(p * (1.0 - p) / nn + z2 / (4.0 * nn * nn));
  out.p = p;
  // Exact ends at k = 0 and k = n (the formula gives them up to rounding).
  out.low = k == 0 ? 0.0 : std::clamp(centre - half, 0.0, 1.0);
  out.high = k == n ? 1.0 : std::clamp(centre + half, 0.0, 1.0);
  return out;
}

}  // namespace cordgrasp
