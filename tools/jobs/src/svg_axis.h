#pragma once
// Axes of the inline SVG plots in report.html (trace_plot_svg, first_fc_cdf_svg).
#include <cmath>

namespace cordgrasp {

/// A round tick step (1, 2 or 5 × 10^k) giving two to five intervals up to `max` (> 0).
inline double tick_step(double max) {
  const double raw = max / 5.0;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 5.0})
    if (m * decade >= raw) return m * decade;
  return 10.0 * decade;
}

/// One axis: values from 0 to `top`, ticks every `step` (a non-positive or non-finite `max`
/// gives 0 to 1).
struct Axis {
  double step = 1.0;
  double top = 1.0;
  explicit Axis(double max) {
    if (!(max > 0.0) || !std::isfinite(max)) max = 1.0;
    step = tick_step(max);
    top = step * std::ceil(max / step - 1e-9);
  }
};

}  // namespace cordgrasp
