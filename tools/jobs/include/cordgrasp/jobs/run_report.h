#pragma once
// report.md of `cordgrasp run`: a human summary of one plan → validate → render job.
#include <optional>
#include <string>
#include <vector>

#include "cordgrasp/jobs/plan_json.h"
#include "cordgrasp/jobs/sim_json.h"

namespace cordgrasp {

/// Pictures of one grasp, file names relative to the report's folder.
struct GraspPictures {
  std::string planned;                 ///< the planned grasp with cords and contacts
  std::vector<std::string> snapshots;  ///< physics frames (after close, lift, shake)
};

/// Everything report.md shows.
struct RunReport {
  PlanDocument plan;
  std::optional<SimDocument> sim;      ///< unset when physics was skipped
  std::vector<GraspPictures> pictures; ///< one per grasp shown (may be empty: no rendering)
  std::string sheet;                   ///< contact sheet of all grasps ("" if none)
  double plan_wall_s = 0.0;
  double sim_wall_s = 0.0;
  double render_wall_s = 0.0;
  /// The signal that stopped the run early ("SIGINT"), "" when it ran to its end, and where:
  /// "planning", "physics after 1 of 3 grasps", "rendering after 2 of 3 grasps".
  std::string interrupted;
  std::string interrupted_at;
};

/// Markdown text of report.md: inputs and parameters, the grasps (α, ε, χ, region, physics
/// outcome), stage timings and the pictures. Grasps listed in the order planned.
std::string run_report_markdown(const RunReport& report);

}  // namespace cordgrasp
