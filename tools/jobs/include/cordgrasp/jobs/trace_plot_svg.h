#pragma once
// The object in the hand over simulated time, as an inline SVG plot for report.html.
#include <string>
#include <vector>

#include "cordgrasp/jobs/run_report.h"
#include "cordgrasp/sim/sim_result.h"

namespace cordgrasp {

/// Size of trace_plot_svg()'s drawing [CSS px].
struct TracePlotParams {
  int width_px = 720;
  int height_px = 240;
};

/// SVG element plotting a grasp's trace: the object's shift [mm] (left axis) and turn [°]
/// (right axis) against simulated time [s], each phase shaded and named (segments such as
/// "shake x" belong to their phase), and, when `result` did not hold, a red line at the end of
/// the phase that failed, captioned with its outcome. "" for an empty trace.
std::string trace_plot_svg(const std::vector<TraceSample>& trace, const SimResult* result,
                           const TracePlotParams& params = {});

}  // namespace cordgrasp
