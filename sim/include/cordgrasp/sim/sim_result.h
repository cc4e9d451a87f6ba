#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "cordgrasp/sim/sim_params.h"

namespace cordgrasp {

/// Outcome of one phase of the physics validation (docs/physics.md §4).
enum class Outcome {
  kHeld,      ///< object moved < held_translation_m, turned < held_rotation_rad relative to the
              ///< hand since the end of closing, and still touches the hand
  kSlipped,   ///< still touches the hand but moved or turned more than that
  kDropped,   ///< no longer touches the hand
  kUnstable,  ///< NaN or a body faster than unstable_speed_mps: the simulation blew up
  kNotRun,    ///< not run (not requested, or an earlier phase failed)
};

/// "held", "slipped", "dropped", "unstable", "not_run".
const char* to_string(Outcome outcome);

/// Parses the names of to_string(Outcome). @throws std::invalid_argument otherwise.
Outcome parse_outcome(const std::string& text);

/// How many of `outcomes` are held.
int count_held(const std::vector<Outcome>& outcomes);

/// What one phase did and measured. Poses compare the object in the hand base frame with
/// its pose right after closing (for settle and close: with the planned pose).
struct PhaseResult {
  std::string name;                 ///< settle, close, lift, shake, gravity6
  Outcome outcome = Outcome::kNotRun;
  std::string detail;               ///< e.g. the segment that failed ("shake y", "gravity -x")
  double translation_m = 0.0;       ///< object displacement relative to the hand at the end [m]
  double rotation_rad = 0.0;        ///< object rotation relative to the hand at the end [rad]
  double max_translation_m = 0.0;   ///< largest displacement seen during the phase [m]
  bool in_contact = false;          ///< a hand–object contact within contact_distance_m at end
  int contact_count = 0;            ///< hand–object contact points at the end
  int max_contact_count = 0;        ///< most contact points at any step
  double max_penetration_m = 0.0;   ///< deepest hand–object penetration during the phase [m]
  /// Effort each joint's servo (mimic joints: their gear) applied in the last step, one entry
  /// per HandModel joint, 0 for fixed joints [N·m or N].
  std::vector<double> joint_efforts;
  /// From the close on: the largest effort a squeezing joint applied toward closing in the last
  /// step, over its squeeze effort; ≥ 1: a finger presses the object with its full squeeze, ≈ 0:
  /// none presses it (0 before the close and when no joint squeezes) [-].
  double squeeze_effort_ratio = 0.0;
  double sim_time_s = 0.0;          ///< simulated time [s]
  double wall_time_s = 0.0;         ///< wall-clock time [s]
  int steps = 0;                    ///< time steps taken
};

/// A finger presses the object when its squeeze joint applies at least this share of its
/// squeeze effort (PhaseResult::squeeze_effort_ratio): pressing fingers end the close at their
/// effort cap (1, or squeeze_hold_factor when pushed back), the others near 0 [-].
inline constexpr double kPressingEffortRatio = 0.5;

/// The object as simulated.
struct SimObjectInfo {
  ObjectShape shape = ObjectShape::kConvexHull;  ///< the shape used (kAuto resolved)
  int parts = 1;                  ///< convex parts (1 for a hull; triangles for GImpact)
  double mass_kg = 0.0;
  double volume_m3 = 0.0;         ///< volume the mass came from [m³]
  bool closed = false;            ///< closed mesh: closed volume; open: shell or hull volume
  Eigen::Vector3d com_O = Eigen::Vector3d::Zero();  ///< centre of mass in the object frame [m]
  Eigen::Vector3d principal_inertia_kgm2 = Eigen::Vector3d::Zero();  ///< about the COM
  double decomposition_s = 0.0;   ///< HACD time (0 when cached or unused) [s]
};

/// Result of validate_grasp(): the phases in the order run and the overall outcome.
struct SimResult {
  /// kHeld when every requested test phase held; otherwise the outcome of the first phase
  /// that did not hold (close with no contact counts as dropped).
  Outcome outcome = Outcome::kNotRun;
  std::vector<PhaseResult> phases;  ///< settle, close, then the tests (gravity6 re-closes)
  SimObjectInfo object;
  Eigen::Isometry3d X_WO = Eigen::Isometry3d::Identity();  ///< object in world at the start
  double wall_time_s = 0.0;         ///< whole validation [s]
  /// The object moved more than SimParams::settle_shift_tolerance_m during settle: the
  /// preshape hand overlaps the object as simulated. For a planner's grasp (whose preshape is
  /// collision-free against the mesh) the collision shape — hull or convex parts — covers space
  /// the mesh leaves free, and the outcome tests that shape more than the grasp.
  bool preshape_overlap = false;
  /// Close moved the object past SimParams::squeeze_shift_limit_m: slipped before the tests.
  bool rejected_in_close = false;
  /// At the end of close, for each planned contact (Grasp::contacts, in order): the distance
  /// in the object frame from the planned contact point to the nearest simulated hand–object
  /// contact point [m]; NaN when the object touches nothing. Empty when close did not run.
  std::vector<double> planned_contact_offsets_m;
  /// GraspSimulation::weight_margin() of the grasp simulated (computed before the first step);
  /// none for a grasp without planned contacts [-].
  std::optional<double> weight_margin;
  bool held() const { return outcome == Outcome::kHeld; }
  /// The phase called `name`, or nullptr.
  const PhaseResult* phase(const std::string& name) const;
  /// The first phase that ran and did not hold, or nullptr.
  const PhaseResult* failed_phase() const;
  /// Lost in lift, shake or gravity6 with no finger pressing the object at the end of the
  /// close (its squeeze_effort_ratio below kPressingEffortRatio).
  bool lost_without_pressing() const;
  /// Lost in lift, shake or gravity6 with a weight_margin below 1: the planned contacts cannot
  /// carry the object's weight within the servos' caps.
  bool lost_below_weight_margin() const;
};

}  // namespace cordgrasp
