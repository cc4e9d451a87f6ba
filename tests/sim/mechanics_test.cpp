// Physics against mechanics: cases whose answer is known on paper. Each test sweeps a load on
// the shipped parallel gripper (docs/physics.md §2–§4) and checks that the simulated threshold
// between held and not held lies within kThresholdRelTol of the analytic one; the pinches also
// check the planner-side weight margin (core weight_margin.h) against the simulated threshold.
//
// The load is gravity during a slow lift (1 cm in 1 s, then a 0.5 s hold without the rest
// exit): the hand's acceleration is at most 5.7735·h/T² = 0.058 m/s² (minimum jerk), 0.6 % of
// g, and it is added to g in every analytic threshold all the same. The squeeze is set
// explicitly (squeeze_weight_factor = 0: the pads press with the prismatic joint's effort limit
// × effort_scale); the analytic thresholds of the pinches use the pressing force the
// simulation reports while it holds the heaviest object that did not slip, not any detail of
// the close phase (measured: on the cone's rim vertices the pads press with 65 of their 80 N,
// so the squeeze spring, full at 5 mm before its rest point, stops ~1 mm past the plan,
// presumably where the margin-shrunk hull's sharp vertex lies).
// Found by the tests/sim/*.cpp glob of tests/CMakeLists.txt: test_sim, label physics.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/kinematics.h"
#include "cordgrasp/core/shapes.h"
#include "cordgrasp/sim/validate_grasp.h"
#include "sim_test_util.h"

namespace cordgrasp {
namespace {

/// Largest relative difference between the simulated and the analytic threshold [-]. The
/// sweep resolves the threshold to ~2 %; the rest covers what the analytic model leaves out:
/// the solver's finite iterations, friction anchors (ERP 0.2) creeping under a load just below
/// the limit, and a slip just above it too slow to leave the held region (2 cm, 15°) in 1.5 s.
constexpr double kThresholdRelTol = 0.1;
/// The sweep brackets the threshold between the nominal analytic mass / and × this [-]...
constexpr double kBracketFactor = 2.0;
/// ...and halves the bracket (in log scale) this often: 4^(1/64) − 1 = 2.2 % resolution.
constexpr int kBisections = 6;

constexpr double kOpenGripper_m = 0.05;  ///< preshape: pads 5 cm from the centre plane
/// The pads touch over a patch: soft-finger contacts of this radius, as the planner models
/// two-finger grippers (and validate_grasp_test.cpp): Bullet spinning friction μ·r·N.
constexpr double kPadPatchRadius_m = 0.005;
/// Slow lift: the dynamic part of the load is 0.6 % of the weight.
constexpr double kLiftHeight_m = 0.01;
constexpr double kLiftTime_s = 1.0;
/// Hold after the lift, with the rest exit off: a slip just past the threshold has time to
/// carry the object out of the held region [s].
constexpr double kLiftHold_s = 0.5;
/// Peak acceleration of a minimum-jerk move of height h in time T is this × h / T² [-]
/// (10/√3).
constexpr double kMinJerkPeakAccelFactor = 5.7735;

const HandModel& gripper() {
  static const HandModel hand = load_hand("parallel_gripper");
  return hand;
}

/// Index of the gripper's driven (master) finger joint; its mimic is the other pad.
int master_joint() { return find_joint(gripper(), "left_finger_joint"); }

/// Pressing force of each pad when the joints push with their effort limits × `effort_scale`
/// [N]: the master's motor pools both joints' limits (docs/physics.md §2), and the coupled pads
/// share it equally, as the box's balance across the pinch asks.
double nominal_pad_force_N(double effort_scale) {
  return gripper().joints[static_cast<size_t>(master_joint())].effort_limit * effort_scale;
}

/// Default parameters with an explicit squeeze (effort limits × `effort_scale`, no weight
/// scaling), soft-finger pads and the slow, static-like lift of lift_only().
SimParams mechanics_params(double effort_scale) {
  SimParams p;
  p.contact.soft_finger_radius_m = kPadPatchRadius_m;
  p.squeeze_weight_factor = 0.0;
  p.effort_scale = effort_scale;
  p.lift_height_m = kLiftHeight_m;
  p.lift_time_s = kLiftTime_s;
  p.lift_hold_s = kLiftHold_s;
  p.rest_exit_time_s = 0.0;
  return p;
}

/// Gravity plus the lift's peak acceleration [m/s²]: the largest specific load of the lift.
double lift_load_mps2(const SimParams& p) {
  return p.gravity_mps2 +
         kMinJerkPeakAccelFactor * p.lift_height_m / (p.lift_time_s * p.lift_time_s);
}

/// The gripper pinching an object at its frame origin from above, pads at ±`half_width_m`
/// along x_O.
Grasp pinch_at_origin(double half_width_m) {
  return test::top_down_pinch(gripper(), Eigen::Vector3d::Zero(), half_width_m, kOpenGripper_m);
}

/// The mass whose weight the pinch's planned contacts carry exactly within the joints' effort
/// limits: GraspSimulation::weight_margin() = 1 [kg]. The margin falls as 1 / mass, so this is
/// the margin at 1 kg. The contacts: each pad touching the object on x_O at ±half_width_m.
double unit_margin_mass_kg(const Mesh& mesh, Grasp grasp, double half_width_m, SimParams params) {
  const std::vector<Eigen::Isometry3d> X_OL = link_poses(gripper(), grasp.q, grasp.X_OB);
  for (const char* name : {"left_finger", "right_finger"}) {
    Contact c;
    c.link = find_link(gripper(), name);
    const double side = X_OL[static_cast<size_t>(c.link)].translation().x() > 0.0 ? 1.0 : -1.0;
    c.p_O = Eigen::Vector3d(side * half_width_m, 0, 0);
    c.n_O = side * Eigen::Vector3d::UnitX();
    grasp.contacts.push_back(c);
  }
  params.mass_kg = 1.0;
  return GraspSimulation(mesh, gripper(), grasp, params).weight_margin() * 1.0;
}

/// Outcome of a sweep: the heaviest mass held, the lightest not held [kg], and the pressing
/// force per pad measured in the lift that held the heaviest mass [N].
struct Threshold {
  double held_kg = 0.0;
  double failed_kg = 0.0;
  double pad_force_N = 0.0;
  int simulations = 0;
  double estimate_kg() const { return std::sqrt(held_kg * failed_kg); }
};

/// Lifts `mesh` pinched by `grasp` with masses between nominal_kg / and × kBracketFactor, and
/// bisects (in log scale) the largest mass that is still held. Fails the test (and returns
/// failed_kg = 0) when the bracket's ends do not hold and fail.
Threshold sweep_mass(const Mesh& mesh, const Grasp& grasp, SimParams params, double nominal_kg) {
  const SimTests lift_only{true, false, false};
  Threshold t;
  const auto lift_held = [&](double mass_kg) {
    params.mass_kg = mass_kg;
    const SimResult r = validate_grasp(mesh, gripper(), grasp, params, lift_only);
    ++t.simulations;
    EXPECT_NE(r.outcome, Outcome::kUnstable) << mass_kg << " kg";
    const PhaseResult* close = r.phase("close");
    EXPECT_TRUE(close != nullptr && close->outcome == Outcome::kHeld) << mass_kg << " kg";
    const PhaseResult* lift = r.phase("lift");
    if (!r.held() || lift == nullptr) return false;
    t.pad_force_N = 0.5 * std::abs(lift->joint_efforts[static_cast<size_t>(master_joint())]);
    return true;
  };
  t.held_kg = nominal_kg / kBracketFactor;
  t.failed_kg = nominal_kg * kBracketFactor;
  if (!lift_held(t.held_kg)) {
    ADD_FAILURE() << "the light end of the sweep, " << t.held_kg << " kg, is not held";
    t.failed_kg = 0.0;
    return t;
  }
  const double light_pad_force_N = t.pad_force_N;
  if (lift_held(t.failed_kg)) {
    ADD_FAILURE() << "the heavy end of the sweep, " << t.failed_kg << " kg, is held";
    t.failed_kg = 0.0;
    return t;
  }
  for (int k = 0; k < kBisections; ++k) {
    const double mid_kg = std::sqrt(t.held_kg * t.failed_kg);
    (lift_held(mid_kg) ? t.held_kg : t.failed_kg) = mid_kg;
  }
  // With the weight scaling off the grip does not depend on the mass.
  EXPECT_NEAR(t.pad_force_N, light_pad_force_N, kThresholdRelTol * light_pad_force_N);
  return t;
}

/// Prints the sweep's result (for the record of how close the simulation comes).
void report(const char* name, const Threshold& t, double analytic_kg) {
  std::cout << name << ": pad force " << t.pad_force_N << " N; held up to " << t.held_kg
            << " kg, not held from " << t.failed_kg << " kg; simulated threshold "
            << t.estimate_kg() << " kg vs analytic " << analytic_kg << " kg ("
            << 100.0 * (t.estimate_kg() / analytic_kg - 1.0) << " %), " << t.simulations
            << " simulations\n";
}

TEST(Mechanics, PinchedBoxHoldsUpToTheMassWhoseWeightEqualsTwiceMuTimesThePadForce) {
  // Analytic answer: two pads press the box with F each; Coulomb friction (Bullet's implicit
  // cone, μ per contact) gives each pad at most μ·F along the face, so the box hangs in the
  // pinch iff 2·μ·F ≥ m·(g + a), a the lift's peak acceleration: m* = 2·μ·F / (g + a). The box
  // is pinched at its centre of mass, so gravity puts no torque on it about the pinch axis.
  // Pads at 20 N (effort scale 1/4 of the URDF's 80 N): m* ≈ 2 kg.
  constexpr double kBoxSide_m = 0.05;
  constexpr double kEffortScale = 0.25;
  const Mesh box = make_box_mesh(Eigen::Vector3d::Constant(kBoxSide_m));
  const SimParams params = mechanics_params(kEffortScale);
  const double mu = params.contact.mu;
  const double nominal_kg = 2.0 * mu * nominal_pad_force_N(kEffortScale) / lift_load_mps2(params);
  const Threshold t = sweep_mass(box, pinch_at_origin(0.5 * kBoxSide_m), params, nominal_kg);
  ASSERT_GT(t.failed_kg, 0.0);
  ASSERT_GT(t.pad_force_N, 0.0);
  const double analytic_kg = 2.0 * mu * t.pad_force_N / lift_load_mps2(params);
  report("pinched box", t, analytic_kg);
  EXPECT_NEAR(t.estimate_kg(), analytic_kg, kThresholdRelTol * analytic_kg);
  // The planner-side weight margin puts the threshold where the simulation does.
  const double margin_kg =
      unit_margin_mass_kg(box, pinch_at_origin(0.5 * kBoxSide_m), 0.5 * kBoxSide_m, params);
  std::cout << "pinched box: weight margin 1 at " << margin_kg << " kg\n";
  EXPECT_NEAR(margin_kg, t.estimate_kg(), kThresholdRelTol * t.estimate_kg());
}

/// A right circular cone of base radius `radius_m` and height `height_m` as an
/// `segments`-gon pyramid: the base in the x–z plane centred at the origin with vertices at
/// (±radius_m, 0, 0), the apex at (0, height_m, 0). Its centre of mass lies at y = height / 4.
Mesh make_cone_along_y(double radius_m, double height_m, int segments) {
  Mesh m;
  m.name = "cone";
  for (int j = 0; j < segments; ++j) {
    const double phi = 2.0 * M_PI * j / segments;
    m.vertices.emplace_back(radius_m * std::cos(phi), 0.0, radius_m * std::sin(phi));
  }
  const int apex = segments;
  const int centre = segments + 1;
  m.vertices.emplace_back(0.0, height_m, 0.0);
  m.vertices.emplace_back(0.0, 0.0, 0.0);
  for (int j = 0; j < segments; ++j) {
    const int k = (j + 1) % segments;
    m.triangles.emplace_back(j, apex, k);
    m.triangles.emplace_back(centre, j, k);
  }
  return m;
}

TEST(Mechanics, ConePinchedAtItsRimTurnsOnceGravitysTorqueExceedsTheSoftFingersTorsion) {
  // Analytic answer: a cone lying along y_O (horizontal) is pinched at the two rim vertices on
  // the x axis, one point contact per pad. Its centre of mass lies d = h/4 off that pinch axis,
  // horizontally, so its weight turns it about the axis with m·(g + a)·d. The only torque the
  // contacts oppose to it is the soft fingers' torsion about their normals (the pinch axis):
  // Bullet's spinning friction, at most μ·r·F per pad (the linear friction forces act on the
  // axis and have no moment about it). It turns iff m·(g + a)·d > 2·μ·r·F:
  // m* = 2·μ·r·F / ((g + a)·d), a fifth (r/d) of the mass the linear friction would hold, so
  // it turns past 15° before it could slide.
  constexpr double kConeRadius_m = 0.025;
  constexpr double kConeHeight_m = 0.1;
  /// 16 sides: the rim has vertices on the pinch axis, and its neighbours are 1.9 mm back, so
  /// each pad touches one vertex.
  constexpr int kConeSides = 16;
  constexpr double kEffortScale = 1.0;  ///< pads at 80 N: m* ≈ 1.6 kg
  constexpr double kComRelTol = 1e-6;
  /// The margin-shrunk hull's rim vertex lies about 1 mm inside the drawn one (a sharp vertex
  /// recedes by more than the margin): the pinch is planned there, as a planner on the
  /// collision shape would, so that a squeeze bounded to a millimetre past the plan reaches it.
  constexpr double kRimVertexInset_m = 1e-3;
  const Grasp pinch = pinch_at_origin(kConeRadius_m - kRimVertexInset_m);
  const Mesh cone = make_cone_along_y(kConeRadius_m, kConeHeight_m, kConeSides);
  const SimParams params = mechanics_params(kEffortScale);
  const double mu = params.contact.mu;
  const double r_m = params.contact.soft_finger_radius_m;
  const double d_m = 0.25 * kConeHeight_m;
  const double nominal_kg =
      2.0 * mu * r_m * nominal_pad_force_N(kEffortScale) / (lift_load_mps2(params) * d_m);
  ASSERT_LT(r_m / d_m, 0.5) << "the torsion, not the linear friction, must give way first";
  const Threshold t = sweep_mass(cone, pinch, params, nominal_kg);
  ASSERT_GT(t.failed_kg, 0.0);
  ASSERT_GT(t.pad_force_N, 0.0);
  // The simulated object's centre of mass is where d says.
  SimParams probe = params;
  probe.mass_kg = t.held_kg;
  const SimResult r = validate_grasp(cone, gripper(), pinch, probe,
                                     SimTests{false, false, false});
  EXPECT_NEAR(r.object.com_O.y(), d_m, kComRelTol * d_m);
  EXPECT_NEAR(r.object.com_O.x(), 0.0, kComRelTol * d_m);
  EXPECT_NEAR(r.object.com_O.z(), 0.0, kComRelTol * d_m);
  const double analytic_kg = 2.0 * mu * r_m * t.pad_force_N / (lift_load_mps2(params) * d_m);
  report("cone torsion", t, analytic_kg);
  EXPECT_NEAR(t.estimate_kg(), analytic_kg, kThresholdRelTol * analytic_kg);
  const double margin_kg =
      unit_margin_mass_kg(cone, pinch, kConeRadius_m - kRimVertexInset_m, params);
  std::cout << "cone torsion: weight margin 1 at " << margin_kg << " kg\n";
  EXPECT_NEAR(margin_kg, t.estimate_kg(), kThresholdRelTol * t.estimate_kg());
}

/// Lifts the gripper with `box` resting on its palm (world_frame kObject: gravity −z_O) under
/// `params` and tells whether the box stays put; the fingers stand wide open, clear of it.
bool box_stays_on_palm(const Mesh& box, const Eigen::Isometry3d& X_OB, const SimParams& params) {
  Grasp g;
  const Eigen::Index n = static_cast<Eigen::Index>(gripper().joints.size());
  g.q = g.q_preshape = clamp_to_limits(
      gripper(), apply_couplings(gripper(), Eigen::VectorXd::Constant(n, kOpenGripper_m)));
  g.X_OB = X_OB;
  g.X_OG = X_OB * root_pose_for_gcp(gripper(), g.q, Eigen::Isometry3d::Identity()).inverse();
  const SimResult r = validate_grasp(box, gripper(), g, params, SimTests{true, false, false});
  EXPECT_NE(r.outcome, Outcome::kUnstable);
  const PhaseResult* close = r.phase("close");
  EXPECT_TRUE(close != nullptr && close->outcome == Outcome::kHeld)
      << "the box must rest on the palm when the lift starts";
  return r.held();
}

TEST(Mechanics, BoxOnATiltedPalmSlidesOnceTheSlopeExceedsMu) {
  // Analytic answer: a box resting on the flat palm tilted by θ is pressed on it with
  // N = m·(g + a)·cos θ and pulled along it with m·(g + a)·sin θ (the lift's acceleration a is
  // vertical like gravity and scales both). Coulomb friction holds it iff the pull is at most
  // μ·N: it slides iff tan θ > μ, whatever its mass and the lift. A cube tips only past
  // tan θ = 1, above the sweep.
  constexpr double kBoxSide_m = 0.04;  ///< on the 5 cm wide palm, between the open fingers
  constexpr double kPalmTop_m = 0.06;  ///< palm face above the gripper base frame (URDF) [m]
  /// The sweep of tan θ stays below tipping (tan θ = 1): μ/1.5 to 1.5·μ [-].
  constexpr double kSlopeBracketFactor = 1.5;
  constexpr double kBoxMass_kg = 0.2;
  SimParams params = mechanics_params(1.0);
  params.world_frame = WorldFrame::kObject;
  params.mass_kg = kBoxMass_kg;
  const double mu = params.contact.mu;
  ASSERT_LT(kSlopeBracketFactor * mu, 1.0);
  const Mesh box_P = make_box_mesh(Eigen::Vector3d::Constant(kBoxSide_m));
  // The box on the palm in the palm frame P (the base frame, lowered so that the palm's face
  // meets the box's bottom face), both turned by θ about y_O (the fingers' opening axis is y_B,
  // so the box slides along x_B, away from the fingers).
  const auto stays = [&](double slope) {
    const Eigen::AngleAxisd R_OP(std::atan(slope), Eigen::Vector3d::UnitY());
    Mesh box = box_P;
    for (Eigen::Vector3d& v : box.vertices) v = R_OP * v;
    Eigen::Isometry3d X_OB = Eigen::Isometry3d::Identity();
    X_OB.linear() = R_OP.toRotationMatrix();
    X_OB.translation() = R_OP * Eigen::Vector3d(0.0, 0.0, -0.5 * kBoxSide_m - kPalmTop_m);
    return box_stays_on_palm(box, X_OB, params);
  };
  double held = mu / kSlopeBracketFactor, slid = mu * kSlopeBracketFactor;
  ASSERT_TRUE(stays(held)) << "tan θ = " << held;
  ASSERT_FALSE(stays(slid)) << "tan θ = " << slid;
  for (int k = 0; k < kBisections; ++k) {
    const double mid = std::sqrt(held * slid);
    (stays(mid) ? held : slid) = mid;
  }
  const double simulated = std::sqrt(held * slid);
  std::cout << "box on tilted palm: held up to tan θ = " << held << ", slid from " << slid
            << "; simulated threshold " << simulated << " vs analytic μ = " << mu << " ("
            << 100.0 * (simulated / mu - 1.0) << " %), " << kBisections + 2 << " simulations\n";
  EXPECT_NEAR(simulated, mu, kThresholdRelTol * mu);
}

}  // namespace
}  // namespace cordgrasp
