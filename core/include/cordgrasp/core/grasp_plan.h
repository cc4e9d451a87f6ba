#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cordgrasp/core/finger_stage.h"
#include "cordgrasp/core/grasp.h"
#include "cordgrasp/core/grasp_diversity.h"
#include "cordgrasp/core/grasp_quality.h"
#include "cordgrasp/core/serialize.h"

namespace cordgrasp {

/// Which planner plans (docs/algorithm.md §10).
enum class PlannerKind {
  kCord,     ///< the cord planner of Li et al. 2015
  kGeneric,  ///< the Simox-style generic baseline
};

/// "cord", "generic".
const char* to_string(PlannerKind planner);

/// Parses the names of to_string(PlannerKind). @throws std::invalid_argument otherwise.
PlannerKind parse_planner_kind(const std::string& text);

/// Parameters shared by the cord and the generic planner.
struct PlanParams {
  int grasps = 1;              ///< stop after this many force-closure grasps
  /// Safety net: wall-clock cap of the whole plan, exploration included [s]. When it fires the
  /// result depends on the machine's speed (PlanStats::timed_out).
  double time_limit_s = 60.0;
  /// Surface sampling (the generic planner, the cord planner's fallback); the cord
  /// exploration's seed is CordParams'.
  std::uint64_t seed = 1;
  FingerParams finger;         ///< finger stage (docs/algorithm.md §7)
  QualityParams quality;       ///< force closure and ε (docs/algorithm.md §8)
  bool roll_retry = true;      ///< cord: retry a failed region rolled 180° about z
  /// The stopping rule: at most this many finger-stage attempts (both planners), so a seed
  /// gives the same plan on any machine. The cord planner also stops when its regions run out.
  int max_attempts = 500;
  /// cord: when its regions or max_attempts are spent with fewer than `grasps` grasps, up to
  /// this many more attempts at sampled surface points, approached to the object's middle (a
  /// hand whose digits do not suit the regions' placement); 0 = none (the paper's planner).
  int fallback_attempts = 500;
  /// Both planners return only grasps that differ pairwise (validated planning accepts so).
  DiversityParams diversity;

  /// Visits every field in declaration order (core/serialize.h).
  template <typename Archive>
  void Serialize(Archive* a) {
    visit_fields(a, CORDGRASP_NVP(grasps), CORDGRASP_NVP(time_limit_s), CORDGRASP_NVP(seed),
                 CORDGRASP_NVP(finger), CORDGRASP_NVP(quality), CORDGRASP_NVP(roll_retry),
                 CORDGRASP_NVP(max_attempts), CORDGRASP_NVP(fallback_attempts),
                 CORDGRASP_NVP(diversity));
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
  int inside_object = 0;       ///< attempts touching a closed object's surface from inside
  int similar = 0;             ///< force-closure grasps not returned: too like an earlier one
  int sampled_attempts = 0;    ///< cord: attempts at sampled surface points (fallback_attempts)
  double setup_s = 0.0;        ///< hand setup and object wrench-space preparation
  double exploration_s = 0.0;  ///< cord exploration
  double finger_s = 0.0;       ///< all finger-stage runs
  double quality_s = 0.0;      ///< all wrench-space evaluations
  double total_s = 0.0;        ///< the whole plan
  std::optional<double> first_force_closure_s;  ///< plan start → first FC grasp
  /// Stopped by time_limit_s (exploration or finger stage) before finding `grasps` grasps:
  /// the result depends on the machine's speed.
  bool timed_out = false;
  bool attempt_budget_reached = false;  ///< stopped by max_attempts before finding `grasps`
  bool interrupted = false;    ///< stopped by a CancelToken (SIGINT) before its other limits

  /// Visits the fields a plan file keeps, in declaration order (core/serialize.h);
  /// `interrupted` is not one: plan.json records it as the document's `interrupted` reason.
  template <typename Archive>
  void Serialize(Archive* a) {
    visit_fields(a, CORDGRASP_NVP(regions), CORDGRASP_NVP(regions_processed),
                 CORDGRASP_NVP(attempts), CORDGRASP_NVP(force_closure), CORDGRASP_NVP(no_contact),
                 CORDGRASP_NVP(one_contact), CORDGRASP_NVP(cannot_retreat),
                 CORDGRASP_NVP(not_force_closure), CORDGRASP_NVP(inside_object),
                 CORDGRASP_NVP(similar), CORDGRASP_NVP(sampled_attempts), CORDGRASP_NVP(setup_s),
                 CORDGRASP_NVP(exploration_s), CORDGRASP_NVP(finger_s), CORDGRASP_NVP(quality_s),
                 CORDGRASP_NVP(total_s), CORDGRASP_NVP(first_force_closure_s),
                 CORDGRASP_NVP(timed_out), CORDGRASP_NVP(attempt_budget_reached));
  }
};

/// Planned grasps (force-closure ones, in the order found) and statistics.
struct PlanResult {
  std::vector<Grasp> grasps;
  PlanStats stats;
};

}  // namespace cordgrasp
