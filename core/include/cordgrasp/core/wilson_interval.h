#pragma once
// The Wilson score interval of a binomial proportion (Wilson 1927; Agresti & Coull 1998,
// "Approximate is better than exact"): the confidence interval of P(held) from k of n trials.

namespace cordgrasp {

/// z of a two-sided 95 % normal interval.
constexpr double kZ95 = 1.959963984540054;

/// A proportion's estimate and its confidence interval, all in [0, 1].
struct ProportionInterval {
  double p = 0.0;     ///< k / n (0 when n = 0)
  double low = 0.0;   ///< lower bound
  double high = 1.0;  ///< upper bound
};

/// Wilson score interval of k successes in n trials at normal quantile z (kZ95: 95 %);
/// n = 0 gives [0, 1].
/// @throws std::invalid_argument unless 0 ≤ k ≤ n and z > 0.
ProportionInterval wilson_interval(int k, int n, double z = kZ95);

}  // namespace cordgrasp
