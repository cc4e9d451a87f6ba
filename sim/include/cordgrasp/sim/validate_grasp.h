#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "cordgrasp/core/grasp.h"
#include "cordgrasp/core/hand_model.h"
#include "cordgrasp/core/mesh.h"
#include "cordgrasp/sim/sim_params.h"
#include "cordgrasp/sim/sim_result.h"

namespace cordgrasp {

/// Which tests validate_grasp() runs after settle and close.
struct SimTests {
  bool lift = true;      ///< lift, then hold (gravity −z_W; SimParams height and durations)
  bool shake = true;     ///< after lift: ±2 cm along x, y, z, then rock ±15° about x, y, z
  bool gravity6 = true;  ///< from the closed grasp again: hand fixed, gravity ±x, ±y, ±z
};

/// Parses "lift,shake,gravity6" (any subset, comma separated). @throws std::invalid_argument.
SimTests sim_tests_from_string(const std::string& text);

/// "lift,shake,gravity6" for the enabled tests.
std::string to_string(const SimTests& tests);

/// World state at the end of a phase, or inside one (SimParams::trace_interval_s), for drawing
/// and tracing (sim never depends on render).
struct PhaseSnapshot {
  std::string phase;                  ///< phase name (gravity6 segments: "gravity6 -x" etc.)
  bool phase_end = true;              ///< false: a trace sample inside the phase
  double sim_time_s = 0.0;            ///< simulated time since the world was built [s]
  /// Object pose in the hand against the phase's reference (the planned pose in settle and
  /// close, the pose right after closing from then on): shift of its centre of mass
  /// [m] and turn [rad], as the outcome measures them; hand–object contacts within
  /// SimParams::contact_distance_m.
  double object_shift_m = 0.0;
  double object_turn_rad = 0.0;
  int contact_count = 0;
  Eigen::Isometry3d X_WO = Eigen::Isometry3d::Identity();  ///< object in world
  std::vector<Eigen::Isometry3d> X_WL;  ///< every HandModel link in world
  Eigen::VectorXd q;                  ///< joint vector (one entry per HandModel joint)
};

/// Called at the end of every phase (and of every shake / gravity6 segment), and with
/// phase_end = false every SimParams::trace_interval_s inside the phases.
using PhaseHook = std::function<void(const PhaseSnapshot&)>;

/// Physics validation of a planned grasp (docs/physics.md §3): settle, close (squeeze), then the
/// tests — lift, shake (continuing from the lifted hand) and gravity6 (a fresh world closed
/// again). Deterministic: the same inputs give the same result (wall times aside).
/// @throws std::invalid_argument when the grasp's joint vectors do not fit the hand, the mesh
/// has no triangle or the hand has no mass.
SimResult validate_grasp(const Mesh& mesh, const HandModel& hand, const Grasp& grasp,
                         const SimParams& params, const SimTests& tests = {},
                         const PhaseHook& hook = {});

/// The bounded close (docs/physics.md §3a) of one grasp as GraspSimulation runs it, per
/// HandModel joint: the reach start and the servos' targets and effort limits. For running the
/// same protocol in another engine (`cordgrasp export --format mjcf`, docs/export.md).
struct BoundedClose {
  Eigen::VectorXd q_start;      ///< joints at the reach start (gap short, clear of the object)
  Eigen::VectorXd q_plan;       ///< planned joints, couplings applied and clamped to the limits
  /// Squeeze targets: squeeze_travel_m past the planned contacts (at each joint's lever) for
  /// the pushing joints, the plan for the others.
  Eigen::VectorXd q_squeeze;
  /// Effort limit of the servo during reach and squeeze [N·m or N]: the weight-sized squeeze
  /// effort for pushing joints, else the effort limit (a master's includes its mimic joints');
  /// 0 for joints the physics locks at the plan (SimParams::lock_passive_joints).
  Eigen::VectorXd effort;
  /// Effort limit once a pushing joint is behind the plan: squeeze_hold_factor × effort, at
  /// most the effort limit [N·m or N]; `effort` for the other joints.
  Eigen::VectorXd hold_effort;
  Eigen::VectorXd push_sign;    ///< +1 / −1: the direction a joint pushes in; 0: holds the plan
  double reach_time_s = 0.0;    ///< duration of the reach from q_start to q_plan [s]
  SimObjectInfo object;         ///< the object as simulated (mass, shape)
};

/// The bounded close of `grasp` (params.squeeze_travel_m > 0 and reach_start_gap_m > 0): builds
/// the GraspSimulation world (the reach start is checked clear of the object there) and reads
/// its close targets. @throws std::invalid_argument as validate_grasp(), or when the params
/// have no bounded close.
BoundedClose bounded_close(const Mesh& mesh, const HandModel& hand, const Grasp& grasp,
                           const SimParams& params);

/// The simulation behind validate_grasp(), one phase per call, for callers that want to
/// interleave their own checks or drawing. Phases must run in protocol order (settle, close,
/// then lift/shake or gravity6); each returns its PhaseResult. Not copyable; not thread-safe
/// (one instance per thread; instances in different threads are independent).
class GraspSimulation {
 public:
  /// Builds the world: object at X_WO (params.world_frame), hand base at X_WO·X_OB in preshape.
  /// @throws std::invalid_argument as validate_grasp().
  GraspSimulation(const Mesh& mesh, const HandModel& hand, const Grasp& grasp,
                  const SimParams& params);
  ~GraspSimulation();
  GraspSimulation(const GraspSimulation&) = delete;
  GraspSimulation& operator=(const GraspSimulation&) = delete;

  /// Settle: gravity off, joints held at the reach start (the preshape, or part of the way to
  /// the plan: SimParams::reach_start_fraction), hand at the planned pose, object at rest.
  PhaseResult settle();
  /// Close: reach — all driven joints follow minimum-jerk paths from the reach start to the plan,
  /// arriving together; squeeze — actor joints are driven past the plan (in the actors'
  /// closing directions) until they stall or squeeze_max_time_s, the others hold the plan.
  /// Sets the reference pose of the object in the hand. No contact at the end = kDropped.
  PhaseResult close();
  /// Lift: gravity −z_W; the hand rises lift_height_m in lift_time_s, then holds lift_hold_s
  /// (less with SimParams::rest_exit_time_s; early exits: SimParams::exit_on_failure).
  PhaseResult lift();
  /// Shake: gravity on; ±shake_amplitude_m along x_W, y_W, z_W (shake_time_s each), then rock
  /// ±rock_angle_rad about x_W, y_W, z_W through the GCP (rock_time_s each). Starts and ends
  /// at rest (faded sinusoids).
  PhaseResult shake();
  /// Gravity6: hand fixed; gravity along +x, −x, +y, −y, +z, −z of W for gravity6_time_s each
  /// (less with SimParams::rest_exit_time_s).
  PhaseResult gravity6();

  /// The world runs on `duration_s` with the hand held where it is (gravity as in the last
  /// phase), for the pictures of a failure: the segment hook gets samples labelled `label`
  /// (SimParams::trace_interval_s) and a last one; stops once the object is drop_distance_m
  /// off. No result: the outcome was decided before.
  void coast(double duration_s, const std::string& label);

  /// Current world state labelled `phase`.
  PhaseSnapshot snapshot(const std::string& phase) const;
  /// For each planned contact of the grasp: the distance in the object frame from its point to
  /// the nearest hand–object contact point Bullet has now (within contact_distance_m) [m];
  /// NaN where there is none (SimResult::planned_contact_offsets_m).
  std::vector<double> planned_contact_offsets() const;
  /// The object as simulated (mass, shape, parts).
  const SimObjectInfo& object_info() const;
  /// Object frame in world at the start.
  Eigen::Isometry3d X_WO_start() const;
  /// Weight margin (core weight_margin.h) of the planned contacts as this world tests them:
  /// the simulated object's mass and centre of mass, gravity as in lift (SimParams::
  /// world_frame), each joint's torque within what its servo resists (its effort limit; for a
  /// pushing joint of the bounded close BoundedClose::hold_effort; locked joints rigid).
  /// Below 1 the planned contacts cannot carry the object's weight in this hand.
  double weight_margin() const;
  /// Sets a hook called by shake() and gravity6() at the end of each segment, and every
  /// SimParams::trace_interval_s of simulated time inside every phase (phase_end = false).
  void set_segment_hook(PhaseHook hook);

 private:
  struct Impl;
  friend BoundedClose bounded_close(const Mesh&, const HandModel&, const Grasp&,
                                    const SimParams&);
  std::unique_ptr<Impl> impl_;
};

/// Link poses of the hand after building its btMultiBody (fixed joints merged, links at their
/// principal inertia frames) for joint vector q with the root link at X_WB, read back from
/// Bullet's forward kinematics: equal to link_poses() when the model is built right. Joints
/// flagged in `locked` (per HandModel joint) are built as fixed joints at their value in q.
std::vector<Eigen::Isometry3d> multibody_link_poses(const HandModel& hand,
                                                    const Eigen::VectorXd& q,
                                                    const Eigen::Isometry3d& X_WB,
                                                    const std::vector<bool>& locked = {});

}  // namespace cordgrasp
