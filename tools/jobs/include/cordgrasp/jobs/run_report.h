#pragma once
// report.md of `cordgrasp run`: a human summary of one plan → validate → render job.
#include <optional>
#include <string>
#include <vector>

#include "cordgrasp/jobs/plan_json.h"
#include "cordgrasp/jobs/sim_json.h"

namespace cordgrasp {

/// The object in the hand at one moment of the physics (the trace of `validate --trace`).
struct TraceSample {
  std::string phase;             ///< close, lift, shake, gravity6 (segments: "shake x", ...)
  bool phase_end = false;        ///< the last sample of a phase (or segment)
  double sim_time_s = 0.0;       ///< simulated time since the world was built [s]
  double object_shift_m = 0.0;   ///< shift of the object's centre of mass from its reference
  double object_turn_rad = 0.0;  ///< turn of the object from its reference
  int contacts = 0;              ///< hand–object contacts
};

/// Pictures of one grasp, file names relative to the report's folder.
struct GraspPictures {
  std::string planned;                 ///< the planned grasp with cords and contacts
  std::vector<std::string> snapshots;  ///< physics frames (after close, lift, shake)
  std::string animation;               ///< animated WebP of the physics ("" if none)
  std::vector<TraceSample> trace;      ///< the physics over time (empty if none)
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
