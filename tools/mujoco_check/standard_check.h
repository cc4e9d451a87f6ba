#pragma once
// Protocol `standard` (docs/physics.md §3, §3a) in MuJoCo, on a scene written by `cordgrasp
// export --format mjcf`: the bounded close the scene carries per grasp, then lift and shake.
// MuJoCo and Eigen only (see mujoco_check.cpp).
#include <mujoco/mujoco.h>

#include <cmath>
#include <string>
#include <vector>

namespace cordgrasp::mujoco_check {

/// Settings of the MuJoCo run. The protocol's (Bullet's SimParams fields of the same names) come
/// from the scene (read_scene_protocol()): the physics settings its bounded closes were made
/// with. The close's start, targets, effort limits and reach time come from the scene too.
struct StandardCheckParams {
  double time_step_s = 1e-3;  ///< MuJoCo time step [s]; 0: the scene's
  /// MuJoCo only: error at which a servo holding the plan reaches its effort limit (pushing
  /// servos reach theirs at the plan: the scene's squeeze travel) [rad or m].
  double hold_error_rad = 0.02;
  /// MuJoCo only: a pushing servo reaches its effort limit this fraction of its squeeze
  /// travel short of its target (1: at the plan) [-].
  double push_error_fraction = 1.0;
  /// MuJoCo only: noslip solver iterations (friction without creep, as Bullet's) [-].
  int noslip_iterations = 10;
  /// MuJoCo only: damping ratio of the servos (joint damping 2·ratio·√(kp·inertia)) [-].
  double servo_damping_ratio = 1.0;
  double trace_interval_s = 0.0;     ///< > 0: a TraceSample this often [s]
  double mu = 0.0;                   ///< > 0: friction μ of every geom instead of the scene's
  /// MuJoCo only: contact time constant of every geom (solref[0]; 0: the scene's, MuJoCo's
  /// 0.02 s); stiffer contacts than the default come closer to Bullet's rigid ones [s].
  double contact_time_constant_s = 0.004;
  bool implicit = true;              ///< MuJoCo only: the implicit integrator (servo damping)

  // From the scene (SimParams, docs/physics.md §3, §3a, §4):
  double gravity_mps2 = 0.0;   ///< along the approach (+z of the GCP) in lift and shake
  double settle_time_s = 0.0;  ///< settle: gravity off, joints held at the reach start
  /// Squeeze: the servo target approaches the squeeze target as Bullet's velocity servo
  /// does, at this gain × the distance left [1/s].
  double servo_gain_per_s = 0.0;
  double squeeze_max_time_s = 0.0;  ///< close: squeeze stage time limit [s]
  double squeeze_min_time_s = 0.0;  ///< close: stall is not tested before this [s]
  double stall_speed = 0.0;         ///< actor joints slower than this × their speed...
  double stall_time_s = 0.0;        ///< ...and the object at rest this long: stalled [s]
  double lift_height_m = 0.0;       ///< lift: rise against gravity...
  double lift_time_s = 0.0;         ///< ...in this time (minimum jerk) [s]...
  double lift_hold_s = 0.0;         ///< ...then hold at most this long (rest exit) [s]
  double shake_amplitude_m = 0.0;   ///< shake: ±amplitude along x_W, y_W, z_W at once
  double shake_frequency_hz = 0.0;
  double shake_time_s = 0.0;
  double rock_angle_rad = 0.0;  ///< rock: ±angle about x_W, y_W, z_W (GCP)
  double rock_frequency_hz = 0.0;
  double rock_time_s = 0.0;
  double rest_exit_time_s = 0.0;        ///< lift hold ends once the object rests this long [s]
  double rest_drift_m = 0.0;            ///< at rest: its centre of mass moved less [m]...
  double rest_drift_rad = 0.0;          ///< ...and it turned less [rad] in the hand
  double no_contact_exit_time_s = 0.0;  ///< failure exit: no hand–object contact this long
  double held_translation_m = 0.0;      ///< held: moved less than this in the hand...
  double held_rotation_rad = 0.0;       ///< ...turned less than this...
  double contact_distance_m = 0.0;      ///< ...and a hand–object contact this close remains
  double unstable_speed_mps = 0.0;      ///< object or hand base faster: unstable
};

/// `p` with the protocol's fields read from the scene's `sim_<field>` numerics (written by
/// `cordgrasp export --format mjcf`). @throws std::runtime_error naming a missing one.
StandardCheckParams read_scene_protocol(const mjModel* m, StandardCheckParams p);

/// The object in the hand at one moment (a trace row, as `cordgrasp validate --trace`).
struct TraceSample {
  std::string phase;           ///< settle, close, lift, shake, rock
  double sim_time_s = 0.0;
  double object_shift_m = 0.0;   ///< against the planned pose (settle, close), else after close
  double object_turn_rad = 0.0;
  int contacts = 0;              ///< hand–object contacts
};

/// One grasp's run.
struct StandardCheckResult {
  bool held = false;
  /// First phase that failed ("close", "lift", "shake", "rock"), "" when held.
  std::string failed_phase;
  std::string outcome = "held";  ///< held, slipped, dropped or unstable (docs/physics.md §4)
  double close_shift_m = 0.0;    ///< object's centre of mass moved in the hand while closing [m]
  double close_turn_rad = 0.0;   ///< and turned [rad] (against the planned pose)
  double shift_m = 0.0;          ///< after close: in the hand at the end of the last phase run
  double turn_rad = 0.0;
  double squeeze_s = 0.0;        ///< duration of the squeeze stage [s]
  std::vector<TraceSample> trace;  ///< every StandardCheckParams::trace_interval_s
};

/// Runs protocol standard on keyframe (grasp) `key` of `m` (a private copy: gains, damping,
/// force limits and gravity are changed). @throws std::runtime_error when the scene lacks the
/// bodies or the bounded-close numerics of `cordgrasp export`.
StandardCheckResult run_standard_check(mjModel* m, mjData* d, int key,
                                       const StandardCheckParams& p);

}  // namespace cordgrasp::mujoco_check
