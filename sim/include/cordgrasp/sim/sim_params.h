#pragma once
#include <cmath>
#include <optional>
#include <string>

#include "cordgrasp/core/contact_model.h"
#include "cordgrasp/core/serialize.h"
#include "cordgrasp/sim/convex_decomposition.h"

namespace cordgrasp {

/// How the dynamic object collides (docs/physics.md §2).
enum class ObjectShape {
  kAuto,           ///< convex hull for (nearly) convex objects, else kDecomposition
  kConvexHull,     ///< one convex hull of the whole mesh
  kDecomposition,  ///< HACD convex decomposition (compound of hulls), cached per mesh
  kGImpact,        ///< the triangle mesh itself (btGImpactMeshShape)
};

/// "auto", "hull", "decomposition", "gimpact".
const char* to_string(ObjectShape shape);

/// Parses the names of to_string(ObjectShape). @throws std::invalid_argument otherwise.
ObjectShape parse_object_shape(const std::string& text);

/// Where the world frame W is put relative to the object frame O (gravity is always −z_W).
enum class WorldFrame {
  /// W rotated so that the GCP approach axis +z_G points down (−z_W): lift against gravity.
  kApproachDown,
  /// W = O: the object's own frame decides what is up.
  kObject,
};

/// Preset of the protocol's phase durations and early exits (apply_protocol).
enum class Protocol {
  /// Short phases (lift 0.5 s + hold ≤ 0.3 s, 0.5 s per shake and rock axis), early exits and
  /// a reach from near the plan, squeezing 0.5 rad past it: the default before kStandard
  /// (docs/notes/2026-12-01-quick-protocol.md).
  kQuick,
  /// The long protocol (lift 1 s + hold 1 s, 1 s per shake and rock axis), no early exits,
  /// the reach from the preshape: the protocol before the quick one, verdict for verdict.
  kThorough,
  /// The default: the bounded close (the fingers start a few millimetres short of the planned
  /// contacts, close onto them and squeeze at most squeeze_travel_m past them with the
  /// weight-sized force, until the object and the joints rest), quick's lift and early exits,
  /// one shake and one rock segment along all axes at once (docs/physics.md §3a).
  kStandard,
};

/// "quick", "thorough", "standard".
const char* to_string(Protocol protocol);

/// Parses the names of to_string(Protocol). @throws std::invalid_argument otherwise.
Protocol parse_protocol(const std::string& text);

/// "approach_down", "object".
const char* to_string(WorldFrame frame);

/// Parses the names of to_string(WorldFrame). @throws std::invalid_argument otherwise.
WorldFrame parse_world_frame(const std::string& text);

/// Parameters of the physics validation; docs/physics.md §5 gives each default's reason.
struct SimParams {
  // --- Contact ---------------------------------------------------------------------------
  /// Friction μ and soft-finger radius of finger–object contacts: the planner's ContactModel.
  ContactModel contact;
  /// Collision margin of hand link shapes [m]; hulls are shrink-wrapped by it.
  double link_margin_m = 0.5e-3;
  /// Collision margin of object hulls and GImpact triangles [m].
  double object_margin_m = 0.5e-3;

  // --- Integration and solver ------------------------------------------------------------
  /// Fixed time step [s] (preset): 1/960 s in quick and thorough; fast's 1/480 s halves the
  /// steps but loses grasps that thorough holds (docs/physics.md §5).
  double time_step_s = 1.0 / 960.0;
  /// Sequential-impulse iterations per step (preset): 30 in standard, 50 in quick and thorough.
  int solver_iterations = 30;
  /// Error reduction of contacts and joint constraints (Bullet erp, erp2) [0..1]; Bullet's.
  double erp = 0.2;
  /// Contact stiffness [N/m]; 0: rigid contacts (compliant ones lost Schunk grasps).
  double contact_stiffness_Npm = 0.0;
  /// Contact damping [N·s/m], used with contact_stiffness_Npm > 0.
  double contact_damping_Nspm = 0.0;
  /// Bullet polyhedral features on hulls and boxes; off: Bullet 3.24 then ignores the margins.
  bool polyhedral_contacts = false;
  /// Error reduction of friction anchors [0..1]; Bullet's default.
  double friction_erp = 0.2;
  /// Constraint force mixing (softness) of every constraint [-]; 0: no artificial softness.
  double cfm = 0.0;
  /// Allowed penetration before contacts push back [m]; 0: the margins cushion already.
  double linear_slop_m = 0.0;
  /// Error reduction of the mimic gear constraints [0..1]: mimics follow within a few steps.
  double gear_erp = 0.5;
  /// Early exit once an iteration's squared impulse change is below this [N²·s²]; 0: never.
  double solver_residual_threshold = 0.0;
  /// Friction as Bullet's implicit cone (true: the planner's cone) or a pyramid (false).
  bool cone_friction = true;
  /// Warm-start multibody contacts from the last step's impulses; off: costs more than it gains.
  bool articulated_warmstarting = false;

  // --- Object ------------------------------------------------------------------------------
  /// Object density [kg/m³] (mass = density × closed volume); half water: hollow objects.
  double density_kgm3 = 500.0;
  /// Open (non-watertight) meshes: the mass is density × surface area × this shell thickness,
  /// at most density × convex-hull volume; 0: the hull's volume (docs/physics.md §2) [m].
  double open_mesh_shell_m = 0.01;
  /// Object mass [kg] overriding density × volume (CLI --mass); the inertia scales with it.
  std::optional<double> mass_kg;
  /// Collision shape of the object; kAuto: HACD parts hold the most grasps on handles.
  ObjectShape object_shape = ObjectShape::kAuto;
  /// kAuto uses one hull when closed volume / hull volume ≥ this, i.e. nearly convex [-].
  double convex_volume_ratio = 0.95;
  /// HACD parameters of the object decomposition (convex_decomposition.h).
  DecompositionParams decomposition;
  /// Directory of the on-disk decomposition cache, keyed by mesh hash; empty: memory only.
  std::string decomposition_cache_dir;
  /// Centre of mass moved from the solid's (or shell's) by this along x_O, y_O, z_O [m]; the
  /// inertia follows (parallel axes). 0: the uniform solid's (uncertain trials move it).
  double com_offset_x_m = 0.0;
  double com_offset_y_m = 0.0;  ///< ... along y_O [m]
  double com_offset_z_m = 0.0;  ///< ... along z_O [m]

  // --- Hand --------------------------------------------------------------------------------
  /// Peak reach speed per unit of an actor's direction_speed [rad/s], capped by the URDF.
  double close_speed = 1.5;
  /// Squeeze spring's rest point past the plan, revolute joints [rad]; shallower lost grasps.
  double squeeze_rad = 0.5;
  /// The same for prismatic joints [m]; < 1 cm, so pads planned 1 cm short never reach.
  double squeeze_m = 0.005;
  /// Effort limit of revolute joints whose URDF gives none [N·m]: finger-motor scale.
  double default_effort_Nm = 2.0;
  /// Effort limit of prismatic joints whose URDF gives none [N]: gripper-motor scale.
  double default_effort_N = 50.0;
  /// Multiplies every effort limit [-]; 1: the URDF's efforts.
  double effort_scale = 1.0;
  /// Grasp force in proportion to the object's weight: the squeeze efforts (kept while lifting
  /// and shaking) are scaled down, all actor joints alike, to the smallest fraction at which
  /// every joint with a planned contact still presses it with this × m·g / μ (its lever:
  /// contact_levers); never up. 0: the effort limits alone [-].
  double squeeze_weight_factor = 30.0;
  /// Squeeze as the spring above (true) or with full effort up to the rest point (false).
  bool compliant_squeeze = true;
  /// Bounded squeeze (> 0): each actor joint with a planned contact is driven to this far past
  /// its planned contacts (travel / the joint's contact lever; prismatic: travel), pushing with
  /// its squeeze effort, reach included, until it gets there; actor joints without a contact
  /// hold the plan. Replaces squeeze_rad / squeeze_m and the spring; 0: off (preset) [m].
  double squeeze_travel_m = 1e-3;
  /// Bounded squeeze: a finger pushed back behind the plan resists with this × its squeeze
  /// effort (at most its effort limit) [-].
  double squeeze_hold_factor = 3.0;
  /// Joint servo gain: commanded speed = gain × error, capped [1/s]; stiff tracking.
  double servo_gain_per_s = 20.0;
  /// Speed cap of joints that only hold their planned value [rad/s; prismatic 0.1× in m/s].
  double hold_speed = 1.0;
  /// Reflected actuator inertia about revolute joints [kg·m²]: real drives have it.
  double armature_kgm2 = 1e-3;
  /// Reflected actuator inertia of prismatic joints, as mass [kg].
  double armature_kg = 0.5;
  /// Lock joints no actor drives at their planned values, as the planner's closing does.
  bool lock_passive_joints = true;
  /// Cancel gravity on the hand, as an arm's controller would: only the grasp is tested.
  bool hand_gravity_compensation = true;
  /// Hand base mass and inertia × this, so contacts barely deflect the "arm" [-].
  double base_mass_scale = 1000.0;

  // --- Protocol (docs/physics.md §3) -------------------------------------------------------
  // Defaults: Protocol::kStandard; apply_protocol() sets every field marked "(preset)".
  /// The preset the "(preset)" fields were set from (recorded in sim.json).
  Protocol protocol = Protocol::kStandard;
  WorldFrame world_frame = WorldFrame::kApproachDown;
  double gravity_mps2 = 9.81;         ///< magnitude, along −z_W in lift/shake
  double settle_time_s = 0.01;        ///< settle: gravity off, reach start held (preset)
  double squeeze_max_time_s = 0.3;    ///< close: squeeze stage time limit (preset)
  double squeeze_ramp_s = 0.1;        ///< close: the squeeze effort ramps in linearly over this
  double squeeze_min_time_s = 0.05;   ///< close: stall is not tested before this
  /// close: actor joints slower than this × their |direction_speed| [rad/s or m/s] (bounded
  /// close: moved less than this × that speed × stall_time_s over the window)...
  double stall_speed = 0.02;
  double stall_time_s = 0.05;         ///< ...for this long have stalled
  double lift_height_m = 0.03;        ///< lift: rise along +z_W... (preset)
  double lift_time_s = 0.27;          ///< ...in this time (minimum-jerk profile)... (preset)
  double lift_hold_s = 0.3;           ///< ...then hold at most this long (preset)
  double shake_amplitude_m = 0.005;   ///< shake: ±amplitude along x_W, y_W, z_W (preset)
  double shake_frequency_hz = 4.0;    ///< (preset; at least 1 / shake_time_s is used: both
                                      ///< ways)
  double shake_time_s = 0.25;         ///< per axis (preset)
  double rock_angle_rad = 15.0 * M_PI / 180.0;  ///< then ±angle about x_W, y_W, z_W (GCP)
  double rock_frequency_hz = 2.0;  ///< (preset; at least 1 / rock_time_s is used: tilts
                                   ///< both ways)
  double rock_time_s = 0.5;        ///< per axis (preset)
  /// Shake and rock along / about x_W, y_W and z_W at once: one segment of shake_time_s and
  /// one of rock_time_s, each axis's sine a third of a period after the last (a Lissajous
  /// path), instead of one segment per axis (preset).
  bool shake_all_axes_at_once = true;
  double gravity6_time_s = 0.5;       ///< gravity6: at most this per direction ±x, ±y, ±z,
                                      ///< hand fixed (preset)
  /// Reach start: before settle the fingers are put this fraction of the way from the preshape
  /// to the plan (0: the preshape), backing off in quarters to 0 while they would come closer
  /// than reach_start_clearance_m to the object's collision shape [-] (preset).
  double reach_start_fraction = 0.0;
  /// Clearance the fingers keep from the object at the reach start [m].
  double reach_start_clearance_m = 1e-3;
  /// Reach start gap (> 0, instead of reach_start_fraction): every actor joint with a planned
  /// contact starts gap / its contact lever short of the plan toward the preshape, the gap
  /// doubling (three times, then the preshape) while a finger is closer than
  /// reach_start_clearance_m to the object (preset) [m].
  double reach_start_gap_m = 3e-3;

  // --- Early exits --------------------------------------------------------------------------
  /// Rest exit: the lift's hold and each gravity6 direction end once the object has been at
  /// rest relative to the hand this long (0: off) [s] (preset).
  double rest_exit_time_s = 0.1;
  /// At rest: in that time its centre of mass moved less than this in the hand [m]... (its
  /// speed is no test: rigid contacts keep a held object vibrating at 1–6 cm/s)
  double rest_drift_m = 5e-4;
  /// ...and it turned less than this in the hand [rad].
  double rest_drift_rad = 0.01;
  /// Failure exit: lift, shake and gravity6 end at once when the object has moved or turned
  /// past held_translation_m / held_rotation_rad, or has not touched the hand for
  /// no_contact_exit_time_s (false: only at drop_distance_m) (preset). An object falling out
  /// between the fingers is then `slipped`, where the whole phase would end in `dropped`.
  bool exit_on_failure = true;
  /// Failure exit: time without any hand–object contact that ends the phase [s].
  double no_contact_exit_time_s = 0.02;

  // --- Outcome -----------------------------------------------------------------------------
  double held_translation_m = 0.02;               ///< held: object moved less than this...
  double held_rotation_rad = 15.0 * M_PI / 180.0;  ///< ...and turned less than this...
  double contact_distance_m = 1e-3;  ///< ...and a hand–object contact this close remains
  double unstable_speed_mps = 10.0;  ///< any body faster than this, or NaN = unstable
  double drop_distance_m = 0.10;     ///< a phase stops early once the object is this far off
  /// Settle shift beyond which the preshape overlaps the object (preshape_overlap) [m].
  double settle_shift_tolerance_m = 1e-3;
  /// Early rejection: a grasp whose object moved farther than this from its planned pose in
  /// the hand while closing is slipped in close, before lift and shake (0: off) [m].
  double squeeze_shift_limit_m = 0.0;

  // --- Tracing -----------------------------------------------------------------------------
  /// > 0: the phase hook also gets a snapshot this often inside the phases [s]; 0: off.
  double trace_interval_s = 0.0;
  /// With a phase hook (pictures, trace): after a test fails, the world runs on this long
  /// with the hand held still, so pictures show where the object goes [s]. Results unchanged.
  double failure_tail_s = 0.5;

  /// Visits every field in declaration order (core/serialize.h).
  template <typename Archive>
  void Serialize(Archive* a) {
    visit_fields(a, CORDGRASP_NVP(contact), CORDGRASP_NVP(link_margin_m),
                 CORDGRASP_NVP(object_margin_m), CORDGRASP_NVP(time_step_s),
                 CORDGRASP_NVP(solver_iterations), CORDGRASP_NVP(erp));
    a->Visit(CORDGRASP_NVP(contact_stiffness_Npm));
    a->Visit(CORDGRASP_NVP(contact_damping_Nspm));
    visit_fields(a, CORDGRASP_NVP(polyhedral_contacts), CORDGRASP_NVP(friction_erp),
                 CORDGRASP_NVP(cfm), CORDGRASP_NVP(linear_slop_m), CORDGRASP_NVP(gear_erp),
                 CORDGRASP_NVP(solver_residual_threshold), CORDGRASP_NVP(cone_friction),
                 CORDGRASP_NVP(articulated_warmstarting), CORDGRASP_NVP(density_kgm3),
                 CORDGRASP_NVP(open_mesh_shell_m),
                 CORDGRASP_NVP(mass_kg), CORDGRASP_NVP(object_shape),
                 CORDGRASP_NVP(convex_volume_ratio), CORDGRASP_NVP(decomposition),
                 CORDGRASP_NVP(decomposition_cache_dir), CORDGRASP_NVP(com_offset_x_m),
                 CORDGRASP_NVP(com_offset_y_m), CORDGRASP_NVP(com_offset_z_m),
                 CORDGRASP_NVP(close_speed),
                 CORDGRASP_NVP(squeeze_rad), CORDGRASP_NVP(squeeze_m));
    a->Visit(CORDGRASP_NVP(default_effort_Nm));
    a->Visit(CORDGRASP_NVP(default_effort_N));
    visit_fields(a, CORDGRASP_NVP(effort_scale), CORDGRASP_NVP(squeeze_weight_factor),
                 CORDGRASP_NVP(compliant_squeeze), CORDGRASP_NVP(squeeze_travel_m),
                 CORDGRASP_NVP(squeeze_hold_factor),
                 CORDGRASP_NVP(servo_gain_per_s),
                 CORDGRASP_NVP(hold_speed), CORDGRASP_NVP(armature_kgm2),
                 CORDGRASP_NVP(armature_kg), CORDGRASP_NVP(lock_passive_joints),
                 CORDGRASP_NVP(hand_gravity_compensation), CORDGRASP_NVP(base_mass_scale),
                 CORDGRASP_NVP(protocol), CORDGRASP_NVP(world_frame), CORDGRASP_NVP(gravity_mps2),
                 CORDGRASP_NVP(settle_time_s), CORDGRASP_NVP(squeeze_max_time_s),
                 CORDGRASP_NVP(squeeze_ramp_s), CORDGRASP_NVP(squeeze_min_time_s),
                 CORDGRASP_NVP(stall_speed), CORDGRASP_NVP(stall_time_s),
                 CORDGRASP_NVP(lift_height_m), CORDGRASP_NVP(lift_time_s),
                 CORDGRASP_NVP(lift_hold_s), CORDGRASP_NVP(shake_amplitude_m),
                 CORDGRASP_NVP(shake_frequency_hz), CORDGRASP_NVP(shake_time_s),
                 CORDGRASP_NVP(rock_angle_rad), CORDGRASP_NVP(rock_frequency_hz),
                 CORDGRASP_NVP(rock_time_s), CORDGRASP_NVP(shake_all_axes_at_once),
                 CORDGRASP_NVP(gravity6_time_s),
                 CORDGRASP_NVP(reach_start_fraction), CORDGRASP_NVP(reach_start_clearance_m),
                 CORDGRASP_NVP(reach_start_gap_m),
                 CORDGRASP_NVP(rest_exit_time_s), CORDGRASP_NVP(rest_drift_m),
                 CORDGRASP_NVP(rest_drift_rad), CORDGRASP_NVP(exit_on_failure),
                 CORDGRASP_NVP(no_contact_exit_time_s), CORDGRASP_NVP(held_translation_m),
                 CORDGRASP_NVP(held_rotation_rad), CORDGRASP_NVP(contact_distance_m),
                 CORDGRASP_NVP(unstable_speed_mps), CORDGRASP_NVP(drop_distance_m),
                 CORDGRASP_NVP(settle_shift_tolerance_m), CORDGRASP_NVP(squeeze_shift_limit_m),
                 CORDGRASP_NVP(trace_interval_s), CORDGRASP_NVP(failure_tail_s));
  }
};

/// What a user sets per object on top of a protocol (CLI --mass, --density, --squeeze-weight):
/// a validated plan records them (ValidationParams::physics) so that validating it again tests
/// the same object. Unset fields leave SimParams' values.
struct SimOverrides {
  std::optional<double> mass_kg;                ///< SimParams::mass_kg [kg]
  std::optional<double> density_kgm3;           ///< SimParams::density_kgm3 [kg/m³]
  std::optional<double> squeeze_weight_factor;  ///< SimParams::squeeze_weight_factor [-]

  /// Visits every field in declaration order (core/serialize.h).
  template <typename Archive>
  void Serialize(Archive* a) {
    visit_fields(a, CORDGRASP_NVP(mass_kg), CORDGRASP_NVP(density_kgm3),
                 CORDGRASP_NVP(squeeze_weight_factor));
  }
};

/// Copies the set fields of `overrides` into `params`.
void apply_sim_overrides(const SimOverrides& overrides, SimParams* params);

/// `given` completed from `recorded`: the squeeze factor where `given` has none; mass and
/// density as one choice (the object's weight), taken from `recorded` only when `given` sets
/// neither.
SimOverrides sim_overrides_or(const SimOverrides& given, const SimOverrides& recorded);

/// Sets the "(preset)" fields of `params` (time step, solver iterations, phase durations, shake path, rock
/// frequency, reach start, early exits) and params->protocol to `protocol`'s values; leaves
/// the others.
void apply_protocol(Protocol protocol, SimParams* params);

/// Default SimParams with `protocol`'s preset applied.
SimParams sim_params_for(Protocol protocol);

/// Checks that every number of `params` is finite, within its range where the simulation
/// needs one (time step, iterations, μ, ...) and otherwise not negative.
/// @throws std::invalid_argument naming the first field out of range and its range.
void check_sim_params(const SimParams& params);

}  // namespace cordgrasp
