#pragma once
// Time to the first force-closure grasp over a bench's attempts, as an inline SVG plot for the
// bench's report.html.
#include <string>
#include <vector>

namespace cordgrasp {

/// Size of first_fc_cdf_svg()'s drawing [CSS px].
struct FirstFcPlotParams {
  int width_px = 360;
  int height_px = 200;
};

/// SVG element: the share of `attempts` attempts [%] that had found a force-closure grasp by
/// time t [s] (a step curve over `first_fc_s`, one step per attempt that found one), with a
/// dashed line at the share that found one at all. `first_fc_s` holds the times of the
/// attempts that found a grasp (wall-clock, ≥ 0). "" when `attempts` is 0.
std::string first_fc_cdf_svg(std::vector<double> first_fc_s, int attempts,
                             const FirstFcPlotParams& params = {});

}  // namespace cordgrasp
