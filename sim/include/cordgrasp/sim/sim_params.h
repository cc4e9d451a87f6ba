#pragma once
#include <cmath>
#include <optional>
#include <string>

#include "cordgrasp/core/contact_model.h"
#include "cordgrasp/core/serialize.h"
#include "cordgrasp/sim/convex_decomposition.h"

namespace cordgrasp {

/// How the dynamic object collides (issue 5; docs/physics.md).
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

/// Old name of parse_object_shape.
inline ObjectShape object_shape_from_string(const std::string& text) {
  return parse_object_shape(text);
}

/// Which way the squeeze pushes once the fingers have reached the plan (issue 5; docs/physics.md).
enum class SqueezeDirection {
  /// Every actor joint pushes toward closing with its full effort limit.
  kActor,
  /// The actor joints press the planned contacts along their normals with one common force,
  /// as large as the weakest joint allows (τ = f·Σ Jᵀ(−n)); actors without a contact hold.
  kContactNormals,
};

/// "actor", "contacts".
const char* to_string(SqueezeDirection direction);

/// Parses the names of to_string(SqueezeDirection). @throws std::invalid_argument otherwise.
SqueezeDirection parse_squeeze_direction(const std::string& text);

/// Old name of parse_squeeze_direction.
inline SqueezeDirection squeeze_direction_from_string(const std::string& text) {
  return parse_squeeze_direction(text);
}

/// Where the world frame W is put relative to the object frame O (gravity is always −z_W).
enum class WorldFrame {
  /// W rotated so that the planned GCP approach axis (+z_G) points down (−z_W) and x_G = x_W:
  /// the hand grasps from above and lifts the object against gravity (default).
  kApproachDown,
  /// W = O: the object's own frame decides what is up.
  kObject,
};

/// "approach_down", "object".
const char* to_string(WorldFrame frame);

/// Parses the names of to_string(WorldFrame). @throws std::invalid_argument otherwise.
WorldFrame parse_world_frame(const std::string& text);

/// Parameters of the physics validation (issue 5). Defaults were chosen by measurement; each
/// field says why (docs/physics.md has the numbers and the commands).
struct SimParams {
  // --- Contact ---------------------------------------------------------------------------
  /// Coulomb friction μ of finger–object contacts: the planner's ContactModel (one source of
  /// truth, core/contact_model.h). Bullet multiplies the two bodies' frictions; hand links get
  /// 1 and the object μ, so every finger–object contact uses exactly μ.
  ContactModel contact;
  /// Margin of hand link shapes [m] (≤ 1 mm; hulls are shrink-wrapped by it, bullet_shapes.h).
  double link_margin_m = 0.5e-3;
  /// Margin of object hulls [m] (shrink-wrapped like the links'); GImpact triangles use it too.
  double object_margin_m = 0.5e-3;

  // --- Integration and solver ------------------------------------------------------------
  /// Fixed time step [s] (docs/physics.md). Lift + shake outcomes against a 1/1920 s,
  /// 50-iteration reference, both with 20 iterations: cordgrasp_sah 108–109 / 132 grasps
  /// agree, schunk_sah 68 / 88 (rigid contacts). Compliant contacts at 1/480 s cost half as
  /// much and agree as well for cordgrasp_sah (110–114 / 132) but not for schunk_sah (54 / 88,
  /// fingers slip): not used.
  /// Outcomes of marginal grasps are chaotic: a 1e-15 s change of the step flips 17 of 132.
  double time_step_s = 1.0 / 960.0;
  /// Sequential-impulse iterations per step. Against the 1/1920 s, 50-iteration reference 50
  /// agree on 119 / 132 cordgrasp_sah, 76 / 88 schunk_sah and 40 / 47 panda_hand grasps, 20
  /// on 108–109, 68 and 29: with 20 the panda's pads lose their torsion (docs/physics.md).
  /// The 5 kg box starts to hold at an effort scale of 0.65 with 20, 30 or 50 (Coulomb 0.61).
  int solver_iterations = 50;
  /// Error reduction of contacts and joint constraints (Bullet erp, erp2) [0..1].
  double erp = 0.2;
  /// Contact stiffness of finger–object contacts [N/m] (0: rigid contacts with erp/cfm).
  /// Compliant contacts penetrate force / stiffness and let the solver converge at larger
  /// steps; 2e5 N/m with 400 N·s/m at 1/480 s was measured and rejected (time_step_s).
  double contact_stiffness_Npm = 0.0;
  /// Contact damping [N·s/m] (with contact_stiffness_Npm > 0).
  double contact_damping_Nspm = 0.0;
  /// Give hulls and boxes Bullet's polyhedral features. Off: with SAT off (Bullet's default)
  /// Bullet 3.24 then drops the hulls' margins, so shrink-wrapped hulls sink by the margin
  /// and the 5 kg box needs 0.75 instead of 0.65 of its motors (docs/physics.md).
  bool polyhedral_contacts = false;
  /// Error reduction of friction anchors [0..1].
  double friction_erp = 0.2;
  /// Constraint force mixing (softness) of every constraint [-].
  double cfm = 0.0;
  /// Allowed penetration before contacts push back [m].
  double linear_slop_m = 0.0;
  /// Error reduction of the mimic gear constraints [0..1].
  double gear_erp = 0.5;
  /// The solver stops iterating once the squared impulse change of an iteration is below
  /// this (Bullet leastSquaresResidualThreshold) [N²·s²]; 0 = always run every iteration
  /// (1e-12 saved no time on 220 grasps at the default and changed 2 outcomes).
  double solver_residual_threshold = 0.0;
  /// Friction as Bullet's implicit cone (true) or the two-direction pyramid (false).
  bool cone_friction = true;
  /// Start each step's solve of multibody contacts from the previous step's impulses
  /// (Bullet SOLVER_USE_ARTICULATED_WARMSTARTING, factor 0.85); off in Bullet by default.
  bool articulated_warmstarting = false;

  // --- Object ------------------------------------------------------------------------------
  /// Density of the object [kg/m³]: mass = density × closed volume (convex-hull volume for
  /// open meshes). 500 kg/m³ is half water: light hollow household objects.
  double density_kgm3 = 500.0;
  /// Mass override [kg] (CLI --mass); the inertia is scaled to it.
  std::optional<double> mass_kg;
  /// Collision shape of the object.
  ObjectShape object_shape = ObjectShape::kAuto;
  /// kAuto picks the single hull when closed volume / hull volume ≥ this (open meshes: when
  /// the decomposition has one part) [-].
  double convex_volume_ratio = 0.95;
  /// HACD parameters (convex_decomposition.h).
  DecompositionParams decomposition;
  /// Directory for the on-disk decomposition cache keyed by mesh hash; empty = memory only.
  std::string decomposition_cache_dir;

  // --- Hand --------------------------------------------------------------------------------
  /// Closing speed of actor joints per unit of the actor's direction_speed [rad/s] (a
  /// prismatic joint with speed 0.1 closes at 0.1 × this m/s), capped by the URDF velocity;
  /// the reach stage's minimum-jerk paths peak at this speed.
  double close_speed = 1.5;
  /// Squeeze: each actor joint is a spring whose rest point lies this far past its planned
  /// value, stiffness effort / squeeze (full effort at the plan, less as it closes further)
  /// [rad]...
  double squeeze_rad = 0.5;
  /// ...or [m] for prismatic joints. Less than 1 cm: fingers planned 1 cm short of the object
  /// never reach it.
  double squeeze_m = 0.005;
  /// Effort limit of revolute joints whose URDF gives none (0) [N·m].
  double default_effort_Nm = 2.0;
  /// Effort limit of prismatic joints whose URDF gives none (0) [N].
  double default_effort_N = 50.0;
  /// Multiplies every effort limit (e.g. 0.1 for weak motors) [-].
  double effort_scale = 1.0;
  /// Squeeze direction: actor closing directions, or the planned contacts' normals.
  SqueezeDirection squeeze_direction = SqueezeDirection::kActor;
  /// Squeeze compliantly (the spring above); false: full effort until the joint reaches its
  /// rest point (with kContactNormals too: each pressing joint's full effort limit, in the
  /// direction it presses, not its share of the common force).
  bool compliant_squeeze = true;
  /// Position gain of the joint servos: commanded speed = gain × error, capped [1/s].
  double servo_gain_per_s = 20.0;
  /// Speed cap of joints that only hold their planned value [rad/s or 10× m/s].
  double hold_speed = 1.0;
  /// Reflected actuator (rotor × gear²) inertia added about every revolute joint [kg·m²]:
  /// real finger drives have it, and it keeps light links from slowing the solver down.
  double armature_kgm2 = 1e-3;
  /// The same for prismatic joints, as mass [kg].
  double armature_kg = 0.5;
  /// Joints no actor drives (abduction, thumb opposition) are locked at their planned values,
  /// as the planner never moves them while closing; fewer degrees of freedom, faster.
  bool lock_passive_joints = true;
  /// Cancel gravity on the hand (the arm's controller would): only the grasp is tested.
  bool hand_gravity_compensation = true;
  /// The arm: the hand base's mass and inertia are multiplied by this and its velocity is
  /// commanded every step toward the trajectory, so contacts barely deflect it [-].
  double base_mass_scale = 1000.0;

  // --- Protocol (issue 5) ------------------------------------------------------------------
  WorldFrame world_frame = WorldFrame::kApproachDown;
  double gravity_mps2 = 9.81;         ///< magnitude, along −z_W in lift/shake
  double settle_time_s = 0.05;        ///< settle: gravity off, preshape held
  double squeeze_max_time_s = 0.5;    ///< close: squeeze stage time limit
  double squeeze_ramp_s = 0.1;        ///< close: the squeeze effort ramps in linearly over this
  double squeeze_min_time_s = 0.05;   ///< close: stall is not tested before this
  /// close: actor joints slower than this × their |direction_speed| [rad/s or m/s]...
  double stall_speed = 0.02;
  double stall_time_s = 0.05;         ///< ...for this long have stalled
  double lift_height_m = 0.10;        ///< lift: rise along +z_W...
  double lift_time_s = 1.0;           ///< ...in this time (minimum-jerk profile)...
  double lift_hold_s = 1.0;           ///< ...then hold
  double shake_amplitude_m = 0.02;    ///< shake: ±amplitude along x_W, y_W, z_W in turn
  double shake_frequency_hz = 2.0;
  double shake_time_s = 1.0;          ///< per axis
  double rock_angle_rad = 15.0 * M_PI / 180.0;  ///< then ±angle about x_W, y_W, z_W (GCP)
  double rock_frequency_hz = 1.0;
  double rock_time_s = 1.0;           ///< per axis
  double gravity6_time_s = 1.0;       ///< gravity6: per direction ±x, ±y, ±z, hand fixed

  // --- Outcome -----------------------------------------------------------------------------
  double held_translation_m = 0.02;               ///< held: object moved less than this...
  double held_rotation_rad = 15.0 * M_PI / 180.0;  ///< ...and turned less than this...
  double contact_distance_m = 1e-3;  ///< ...and a hand–object contact this close remains
  double unstable_speed_mps = 10.0;  ///< any body faster than this, or NaN = unstable
  double drop_distance_m = 0.10;     ///< a phase stops early once the object is this far off
  /// Settle keeps the hand still in preshape with gravity off: only a preshape hand that
  /// overlaps the object can move it. Moving more than this sets SimResult::preshape_overlap
  /// [m]. Of the 132 cordgrasp_sah bench grasps settle moved 8 objects by 1.3–34 mm (all 8
  /// failed), one by 0.8 mm (held) and the rest not at all (docs/physics.md).
  double settle_shift_tolerance_m = 1e-3;

  // --- Tracing -----------------------------------------------------------------------------
  /// > 0: the phase hook also gets a snapshot every this many seconds of simulated time inside
  /// the phases (PhaseSnapshot::phase_end false), e.g. to see when an object slips [s].
  double trace_interval_s = 0.0;

  /// Visits every field in declaration order (core/serialize.h).
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit(CORDGRASP_NVP(contact));
    a->Visit(CORDGRASP_NVP(link_margin_m));
    a->Visit(CORDGRASP_NVP(object_margin_m));
    a->Visit(CORDGRASP_NVP(time_step_s));
    a->Visit(CORDGRASP_NVP(solver_iterations));
    a->Visit(CORDGRASP_NVP(erp));
    a->Visit(CORDGRASP_NVP(contact_stiffness_Npm));
    a->Visit(CORDGRASP_NVP(contact_damping_Nspm));
    a->Visit(CORDGRASP_NVP(polyhedral_contacts));
    a->Visit(CORDGRASP_NVP(friction_erp));
    a->Visit(CORDGRASP_NVP(cfm));
    a->Visit(CORDGRASP_NVP(linear_slop_m));
    a->Visit(CORDGRASP_NVP(gear_erp));
    a->Visit(CORDGRASP_NVP(solver_residual_threshold));
    a->Visit(CORDGRASP_NVP(cone_friction));
    a->Visit(CORDGRASP_NVP(articulated_warmstarting));
    a->Visit(CORDGRASP_NVP(density_kgm3));
    a->Visit(CORDGRASP_NVP(mass_kg));
    a->Visit(CORDGRASP_NVP(object_shape));
    a->Visit(CORDGRASP_NVP(convex_volume_ratio));
    a->Visit(CORDGRASP_NVP(decomposition));
    a->Visit(CORDGRASP_NVP(decomposition_cache_dir));
    a->Visit(CORDGRASP_NVP(close_speed));
    a->Visit(CORDGRASP_NVP(squeeze_rad));
    a->Visit(CORDGRASP_NVP(squeeze_m));
    a->Visit(CORDGRASP_NVP(default_effort_Nm));
    a->Visit(CORDGRASP_NVP(default_effort_N));
    a->Visit(CORDGRASP_NVP(effort_scale));
    a->Visit(CORDGRASP_NVP(squeeze_direction));
    a->Visit(CORDGRASP_NVP(compliant_squeeze));
    a->Visit(CORDGRASP_NVP(servo_gain_per_s));
    a->Visit(CORDGRASP_NVP(hold_speed));
    a->Visit(CORDGRASP_NVP(armature_kgm2));
    a->Visit(CORDGRASP_NVP(armature_kg));
    a->Visit(CORDGRASP_NVP(lock_passive_joints));
    a->Visit(CORDGRASP_NVP(hand_gravity_compensation));
    a->Visit(CORDGRASP_NVP(base_mass_scale));
    a->Visit(CORDGRASP_NVP(world_frame));
    a->Visit(CORDGRASP_NVP(gravity_mps2));
    a->Visit(CORDGRASP_NVP(settle_time_s));
    a->Visit(CORDGRASP_NVP(squeeze_max_time_s));
    a->Visit(CORDGRASP_NVP(squeeze_ramp_s));
    a->Visit(CORDGRASP_NVP(squeeze_min_time_s));
    a->Visit(CORDGRASP_NVP(stall_speed));
    a->Visit(CORDGRASP_NVP(stall_time_s));
    a->Visit(CORDGRASP_NVP(lift_height_m));
    a->Visit(CORDGRASP_NVP(lift_time_s));
    a->Visit(CORDGRASP_NVP(lift_hold_s));
    a->Visit(CORDGRASP_NVP(shake_amplitude_m));
    a->Visit(CORDGRASP_NVP(shake_frequency_hz));
    a->Visit(CORDGRASP_NVP(shake_time_s));
    a->Visit(CORDGRASP_NVP(rock_angle_rad));
    a->Visit(CORDGRASP_NVP(rock_frequency_hz));
    a->Visit(CORDGRASP_NVP(rock_time_s));
    a->Visit(CORDGRASP_NVP(gravity6_time_s));
    a->Visit(CORDGRASP_NVP(held_translation_m));
    a->Visit(CORDGRASP_NVP(held_rotation_rad));
    a->Visit(CORDGRASP_NVP(contact_distance_m));
    a->Visit(CORDGRASP_NVP(unstable_speed_mps));
    a->Visit(CORDGRASP_NVP(drop_distance_m));
    a->Visit(CORDGRASP_NVP(settle_shift_tolerance_m));
    a->Visit(CORDGRASP_NVP(trace_interval_s));
  }
};

}  // namespace cordgrasp
