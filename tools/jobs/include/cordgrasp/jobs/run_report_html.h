#pragma once
// report.html of `cordgrasp run`: the grasps' verdicts, pictures, animations, plots of the
// object in the hand over time and a 3D view of each grasp, readable offline from the folder.
#include <string>
#include <vector>

#include "cordgrasp/jobs/run_report.h"

namespace cordgrasp {

/// The 3D view of report.html: three.js in a folder beside it (write_viewer_scripts) and one
/// model script per grasp (write_grasp_model_script).
struct ReportViewer {
  std::string scripts_dir;  ///< folder of the viewer's scripts, relative; "" for none
  /// Per grasp: its model's name ("grasp_0": <name>.glb.js holds <name>.glb); "" for none.
  std::vector<std::string> models;
  std::string unavailable;  ///< why there is no 3D view ("" when there is one)
};

/// HTML text of report.html: the verdict table (per grasp α, ε, the outcome of each physics
/// phase, the shift while closing, held), then per grasp its pictures, its animation, a plot
/// of its trace (trace_plot_svg) and its 3D view, and the stage timings. It refers only to
/// files in its folder (no external URL). Its script `cordgraspSelftest()` checks the page
/// (images decoded, 3D views drawn, no error; tests/browser); with `?selftest` in the URL the
/// page runs it once loaded and writes the result as JSON into the element `#selftest`.
std::string run_report_html(const RunReport& report, const ReportViewer& viewer = {});

}  // namespace cordgrasp
