#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "cordgrasp/core/finger_stage.h"
#include "cordgrasp/core/grasp.h"
#include "cordgrasp/core/grasp_quality.h"

namespace cordgrasp {

/// Parameters shared by the cord and the generic planner.
struct PlanParams {
  int grasps = 1;              ///< stop after this many force-closure grasps
  double time_limit_s = 10.0;  ///< wall-clock cap of the whole plan, exploration included [s]
  std::uint64_t seed = 1;      ///< generic planner sampling (the cord planner's is CordParams')
  FingerParams finger;         ///< finger stage (docs/algorithm.md §7)
  QualityParams quality;       ///< force closure and ε (docs/algorithm.md §8)
  bool roll_retry = true;      ///< cord: retry a failed region rolled 180° about z
  int max_attempts = 1000000;  ///< generic: cap on attempts besides the time limit

  /// Visits every field in declaration order (core/serialize.h).
  template <typename Archive>
  void Serialize(Archive* a) {
    visit_fields(a, CORDGRASP_NVP(grasps), CORDGRASP_NVP(time_limit_s), CORDGRASP_NVP(seed),
                 CORDGRASP_NVP(finger), CORDGRASP_NVP(quality), CORDGRASP_NVP(roll_retry),
                 CORDGRASP_NVP(max_attempts));
  }
};

/// What a plan did, for reports and benchmarks. Times are wall-clock [s].
struct PlanStats {
  int regions = 0;             ///< cord: grasp regions from exploration
  int regions_processed = 0;   ///< cord: regions given to the finger stage
  int attempts = 0;            ///< finger-stage runs (a rolled retry counts as one more)
  int force_closure = 0;       ///< force-closure grasps found
  int no_contact = 0;          ///< attempts ending without contact
  int one_contact = 0;         ///< attempts ending with fewer than min_contacts contacts
  int cannot_retreat = 0;      ///< attempts where the hand could not get collision-free
  int not_force_closure = 0;   ///< attempts with contacts but no force closure
  double setup_s = 0.0;        ///< hand setup and object wrench-space preparation
  double exploration_s = 0.0;  ///< cord exploration
  double finger_s = 0.0;       ///< all finger-stage runs
  double quality_s = 0.0;      ///< all wrench-space evaluations
  double total_s = 0.0;        ///< the whole plan
  std::optional<double> first_force_closure_s;  ///< plan start → first FC grasp
  bool timed_out = false;  ///< stopped by time_limit_s before finding `grasps` grasps
};

/// Planned grasps (force-closure ones, in the order found) and statistics.
struct PlanResult {
  std::vector<Grasp> grasps;
  PlanStats stats;
};

}  // namespace cordgrasp
