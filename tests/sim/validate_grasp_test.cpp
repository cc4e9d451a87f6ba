// Physics validation (docs/physics.md): the parallel gripper on a box, friction, reach and motor
// strength; determinism; object mass properties; parameter parsing.
#include "cordgrasp/sim/validate_grasp.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/kinematics.h"
#include "cordgrasp/core/shapes.h"
#include "sim_test_util.h"

namespace cordgrasp {
namespace {

constexpr double kBoxSide_m = 0.05;
constexpr double kOpenGripper_m = 0.05;        ///< preshape: pads 5 cm from the centre plane
constexpr double kShortOfFaces_m = 0.01;       ///< "fingers 1 cm short of the faces"
constexpr double kHeavyBox_kg = 5.0;           ///< weight 49 N
// The gripper's coupled pads push with 80 N each (its URDF efforts); with μ = 0.5 two pads hold
// up to 2·μ·80·scale N: the threshold for 5 kg is an effort scale of 0.61.
constexpr double kWeakMotors = 0.45;           ///< 36 N of friction < 49 N: slips
constexpr double kStrongMotors = 0.8;          ///< 64 N of friction > 49 N: holds
constexpr double kInertiaRelTol = 1e-9;
/// A held pinch's squeeze spring is a little short of its squeeze force (the pads sit up to a
/// margin inside the faces): relative tolerance on the grip force in lift [-].
constexpr double kGripForceRelTol = 0.1;
/// The gripper's flat pads touch a face over a patch: soft-finger contacts of this radius, as
/// the planner models two-finger grippers (tools/hold_rates.sh). With point contacts nothing
/// but numerical noise keeps the pinched box from spinning about the line through the pads
/// (docs/notes/2026-11-22-physics-measurements.md).
constexpr double kPadPatchRadius_m = 0.005;

/// Simulation parameters of `protocol` (default: the default one) with the pads' soft-finger
/// contacts.
SimParams gripper_params(std::optional<Protocol> protocol = std::nullopt) {
  SimParams params = protocol ? sim_params_for(*protocol) : SimParams{};
  params.contact.soft_finger_radius_m = kPadPatchRadius_m;
  return params;
}

const HandModel& gripper() {
  static const HandModel hand = load_hand("parallel_gripper");
  return hand;
}

const Mesh& box() {
  static const Mesh mesh = make_box_mesh(Eigen::Vector3d::Constant(kBoxSide_m));
  return mesh;
}

/// The gripper pinching the box at its centre, pads `short_m` short of the faces.
Grasp centre_pinch(double short_m = 0.0) {
  return test::top_down_pinch(gripper(), Eigen::Vector3d::Zero(), 0.5 * kBoxSide_m + short_m,
                              kOpenGripper_m);
}

TEST(ValidateGrasp, ParallelGripperPinchingABoxAtItsCentreHoldsThroughEveryTest) {
  const SimResult r = validate_grasp(box(), gripper(), centre_pinch(), gripper_params());
  EXPECT_EQ(r.outcome, Outcome::kHeld);
  for (const char* name : {"settle", "close", "lift", "shake", "gravity6"}) {
    const PhaseResult* p = r.phase(name);
    ASSERT_NE(p, nullptr) << name;
    EXPECT_EQ(p->outcome, Outcome::kHeld) << name << " " << p->detail;
    EXPECT_GT(p->steps, 0) << name;
  }
  const PhaseResult& lift = *r.phase("lift");
  EXPECT_TRUE(lift.in_contact);
  EXPECT_GE(lift.contact_count, 2);
  EXPECT_LT(lift.translation_m, SimParams{}.held_translation_m);
  EXPECT_LT(lift.max_penetration_m, 1e-3);
  // The fingers squeeze: the driven joint pushes (negative = closing for this gripper).
  const int j = find_joint(gripper(), "left_finger_joint");
  EXPECT_LT(lift.joint_efforts[static_cast<size_t>(j)], -1.0);
  EXPECT_NEAR(r.object.mass_kg, SimParams{}.density_kgm3 * std::pow(kBoxSide_m, 3), 1e-12);
}

TEST(ValidateGrasp, SqueezeShiftLimitRejectsTheGraspInCloseBeforeTheTests) {
  // The centre pinch hardly moves the box while closing: a limit below its shift rejects it,
  // one above it (and the default, off) lets it through.
  const SimResult free = validate_grasp(box(), gripper(), centre_pinch(), gripper_params());
  const double shift_m = free.phase("close")->translation_m;
  EXPECT_FALSE(free.rejected_in_close);
  SimParams params = gripper_params();
  params.squeeze_shift_limit_m = 0.5 * shift_m + 1e-12;
  const SimResult r = validate_grasp(box(), gripper(), centre_pinch(), params);
  EXPECT_TRUE(r.rejected_in_close);
  EXPECT_EQ(r.outcome, Outcome::kSlipped);
  EXPECT_EQ(r.phase("close")->outcome, Outcome::kSlipped);
  EXPECT_EQ(r.phase("lift")->outcome, Outcome::kNotRun);
  EXPECT_EQ(r.phase("lift")->steps, 0);
  params.squeeze_shift_limit_m = 2.0 * shift_m + 1e-6;
  const SimResult ok = validate_grasp(box(), gripper(), centre_pinch(), params,
                                      sim_tests_from_string("lift"));
  EXPECT_FALSE(ok.rejected_in_close);
  EXPECT_EQ(ok.outcome, Outcome::kHeld);
}

TEST(ValidateGrasp, ThoroughProtocolHoldsTheCentrePinchThroughItsFullPhases) {
  const SimParams params = gripper_params(Protocol::kThorough);
  const SimResult r = validate_grasp(box(), gripper(), centre_pinch(), params);
  EXPECT_EQ(r.outcome, Outcome::kHeld);
  // No early exit: every phase runs its whole time.
  const auto steps = [&](double t_s) {
    return static_cast<int>(std::lround(t_s / params.time_step_s));
  };
  ASSERT_NE(r.phase("lift"), nullptr);
  EXPECT_EQ(r.phase("lift")->steps, steps(params.lift_time_s + params.lift_hold_s));
  ASSERT_NE(r.phase("shake"), nullptr);
  EXPECT_EQ(r.phase("shake")->steps,
            3 * steps(params.shake_time_s) + 3 * steps(params.rock_time_s));
  ASSERT_NE(r.phase("gravity6"), nullptr);
  EXPECT_EQ(r.phase("gravity6")->steps, 6 * steps(params.gravity6_time_s));
}

TEST(ValidateGrasp, ShakeAlongAllAxesAtOnceRunsOneTranslationAndOneRotationSegment) {
  SimParams params = gripper_params(Protocol::kThorough);
  params.shake_all_axes_at_once = true;
  std::vector<std::string> segments;
  GraspSimulation sim(box(), gripper(), centre_pinch(), params);
  sim.set_segment_hook([&](const PhaseSnapshot& s) { segments.push_back(s.phase); });
  sim.settle();
  sim.close();
  const PhaseResult r = sim.shake();
  EXPECT_EQ(r.outcome, Outcome::kHeld);
  EXPECT_EQ(segments, (std::vector<std::string>{"shake xyz", "shake rock xyz"}));
  const auto steps = [&](double t_s) {
    return static_cast<int>(std::lround(t_s / params.time_step_s));
  };
  EXPECT_EQ(r.steps, steps(params.shake_time_s) + steps(params.rock_time_s));
}

TEST(ValidateGrasp, QuickProtocolEndsTheHoldsOnceTheHeldBoxRests) {
  const SimParams params = gripper_params(Protocol::kQuick);
  const SimResult r = validate_grasp(box(), gripper(), centre_pinch(), params);
  EXPECT_EQ(r.outcome, Outcome::kHeld);
  const auto steps = [&](double t_s) {
    return static_cast<int>(std::lround(t_s / params.time_step_s));
  };
  ASSERT_NE(r.phase("lift"), nullptr);
  EXPECT_GE(r.phase("lift")->steps, steps(params.lift_time_s + params.rest_exit_time_s));
  EXPECT_LT(r.phase("lift")->steps, steps(params.lift_time_s + params.lift_hold_s));
  ASSERT_NE(r.phase("gravity6"), nullptr);
  EXPECT_LT(r.phase("gravity6")->steps, 6 * steps(params.gravity6_time_s));
}

TEST(ValidateGrasp, FailureExitEndsAFailedLiftEarlyWithTheSameOutcome) {
  SimParams params = gripper_params(Protocol::kQuick);
  params.mass_kg = kHeavyBox_kg;
  params.effort_scale = kWeakMotors;
  const SimTests lift_only{true, false, false};
  const SimResult early = validate_grasp(box(), gripper(), centre_pinch(), params, lift_only);
  params.exit_on_failure = false;
  const SimResult full = validate_grasp(box(), gripper(), centre_pinch(), params, lift_only);
  EXPECT_EQ(early.outcome, Outcome::kSlipped);
  EXPECT_NE(full.outcome, Outcome::kHeld);
  EXPECT_NE(full.outcome, Outcome::kUnstable);
  const PhaseResult* a = early.phase("lift");
  const PhaseResult* b = full.phase("lift");
  ASSERT_NE(a, nullptr);
  ASSERT_NE(b, nullptr);
  EXPECT_LT(a->steps, b->steps);
  EXPECT_GE(a->translation_m, params.held_translation_m);
}

/// Every step's snapshot of the shake phase of the centre pinch under `params`.
std::vector<PhaseSnapshot> shake_snapshots(SimParams params) {
  params.trace_interval_s = params.time_step_s;
  std::vector<PhaseSnapshot> shake;
  validate_grasp(box(), gripper(), centre_pinch(), params, SimTests{true, true, false},
                 [&](const PhaseSnapshot& s) {
                   if (s.phase.rfind("shake", 0) == 0) shake.push_back(s);
                 });
  return shake;
}

/// Largest and smallest turn of link `root` about world axis `axis` [rad] over the snapshots
/// after `start` up to the next segment end, relative to its orientation at `start`.
std::pair<double, double> turn_range(std::vector<PhaseSnapshot>::const_iterator start,
                                     std::vector<PhaseSnapshot>::const_iterator end, size_t root,
                                     int axis) {
  const Eigen::Matrix3d R_W0 = start->X_WL[root].linear();
  double most = 0.0, least = 0.0;
  for (auto it = start + 1; it != end && !it->phase_end; ++it) {
    const Eigen::AngleAxisd turn(it->X_WL[root].linear() * R_W0.transpose());
    const double about_axis = (turn.axis() * turn.angle())[axis];
    most = std::max(most, about_axis);
    least = std::min(least, about_axis);
  }
  return {most, least};
}

TEST(ValidateGrasp, QuickRockTiltsTheHandBothWaysAboutEachAxis) {
  /// The faded sine reaches its full amplitude once a quarter period after the fade-in.
  constexpr double kReachedAmplitude = 0.9;
  const SimParams params = gripper_params(Protocol::kQuick);
  const size_t root = static_cast<size_t>(gripper().root_link);
  const std::vector<PhaseSnapshot> shake = shake_snapshots(params);
  const char* axes[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    // The rock about axis a: samples after the previous segment's end up to this one's.
    const std::string before = a == 0 ? "shake z" : std::string("shake rock ") + axes[a - 1];
    const auto start = std::find_if(shake.begin(), shake.end(), [&](const PhaseSnapshot& s) {
      return s.phase_end && s.phase == before;
    });
    ASSERT_NE(start, shake.end()) << before;
    const auto [most, least] = turn_range(start, shake.end(), root, a);
    EXPECT_GT(most, kReachedAmplitude * params.rock_angle_rad) << axes[a];
    EXPECT_LT(least, -kReachedAmplitude * params.rock_angle_rad) << axes[a];
  }
}

TEST(ValidateGrasp, StandardRockTiltsTheHandBothWaysAboutEachAxis) {
  /// Over one period of the faded Lissajous rock each axis's sine reaches at least 68 % of
  /// the amplitude both ways (the axis a third of a period late peaks once during the fade).
  constexpr double kReachedAmplitude = 0.6;
  const SimParams params = gripper_params(Protocol::kStandard);
  const size_t root = static_cast<size_t>(gripper().root_link);
  const std::vector<PhaseSnapshot> shake = shake_snapshots(params);
  // The rock about all axes at once: samples after the translation segment's end.
  const auto start = std::find_if(shake.begin(), shake.end(), [&](const PhaseSnapshot& s) {
    return s.phase_end && s.phase == "shake xyz";
  });
  ASSERT_NE(start, shake.end());
  const char* axes[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    const auto [most, least] = turn_range(start, shake.end(), root, a);
    EXPECT_GT(most, kReachedAmplitude * params.rock_angle_rad) << axes[a];
    EXPECT_LT(least, -kReachedAmplitude * params.rock_angle_rad) << axes[a];
  }
}

/// Joint value of the gripper's driving finger joint at the end of settle under `params`.
double settled_opening(const Grasp& grasp, const SimParams& params) {
  double opening = NAN;
  const int j = find_joint(gripper(), "left_finger_joint");
  validate_grasp(box(), gripper(), grasp, params, SimTests{false, false, false},
                 [&](const PhaseSnapshot& s) {
                   if (s.phase == "settle") opening = s.q[j];
                 });
  return opening;
}

TEST(ValidateGrasp, ReachStartsPartOfTheWayToThePlanUnlessTheFingersWouldEnterTheObject) {
  /// Servo tracking error of the held joint at the end of settle [m].
  constexpr double kHeldJointTol_m = 1e-4;
  const SimParams quick = gripper_params(Protocol::kQuick);
  ASSERT_GT(quick.reach_start_fraction, 0.0);
  // Pads from 5 cm to the faces at 2.5 cm: 80 % of the way leaves them 5 mm off the faces.
  const double f = quick.reach_start_fraction;
  EXPECT_NEAR(settled_opening(centre_pinch(), quick),
              kOpenGripper_m + f * (0.5 * kBoxSide_m - kOpenGripper_m), kHeldJointTol_m);
  EXPECT_NEAR(settled_opening(centre_pinch(), gripper_params(Protocol::kThorough)),
              kOpenGripper_m, kHeldJointTol_m);
  // A plan 2 cm inside the faces (pads 5 mm from the centre): 80 % and 60 % of the way put the
  // pads inside the box, half of 80 % leaves them 7 mm off the faces.
  constexpr double kDeepPlan_m = 0.005;
  const Grasp deep = test::top_down_pinch(gripper(), Eigen::Vector3d::Zero(), kDeepPlan_m,
                                          kOpenGripper_m);
  EXPECT_NEAR(settled_opening(deep, quick),
              kOpenGripper_m + 0.5 * f * (kDeepPlan_m - kOpenGripper_m), kHeldJointTol_m);
}

/// The centre pinch with its planned contacts: each pad on the box face it faces.
Grasp centre_pinch_with_contacts() {
  Grasp g = centre_pinch();
  const auto X_OL = link_poses(gripper(), g.q, g.X_OB);
  for (const Joint& joint : gripper().joints) {
    if (joint.type != JointType::kPrismatic) continue;
    const double x = X_OL[static_cast<size_t>(joint.child_link)].translation().x();
    const double side = x > 0.0 ? 1.0 : -1.0;
    Contact c;
    c.link = joint.child_link;
    c.p_O = Eigen::Vector3d(side * 0.5 * kBoxSide_m, 0, 0);
    c.n_O = Eigen::Vector3d(side, 0, 0);
    g.contacts.push_back(c);
  }
  return g;
}

/// The left pad's joint value (the gripper's opening) at the end of `phase`.
double opening_after(const Mesh& mesh, const Grasp& grasp, const SimParams& params,
                     const std::string& phase) {
  double opening = NAN;
  const int j = find_joint(gripper(), "left_finger_joint");
  validate_grasp(mesh, gripper(), grasp, params, SimTests{false, false, false},
                 [&](const PhaseSnapshot& s) {
                   if (s.phase == phase) opening = s.q[j];
                 });
  return opening;
}

TEST(ValidateGrasp, BoundedCloseStartsAGapShortOfThePlanAndSqueezesAtMostTheTravelPast) {
  /// Servo tracking error of a joint holding its target [m].
  constexpr double kHeldJointTol_m = 1e-4;
  const SimParams standard = gripper_params(Protocol::kStandard);
  ASSERT_GT(standard.reach_start_gap_m, 0.0);
  ASSERT_GT(standard.squeeze_travel_m, 0.0);
  const Grasp pinch = centre_pinch_with_contacts();
  const double plan = 0.5 * kBoxSide_m;
  // Reach start: each pad the gap short of its planned contact (a prismatic lever is 1).
  EXPECT_NEAR(opening_after(box(), pinch, standard, "settle"), plan + standard.reach_start_gap_m,
              kHeldJointTol_m);
  // A box 1 cm narrower than planned: the pads travel squeeze_travel_m past the plan and stop
  // there, short of its faces, instead of closing on it.
  constexpr double kNarrower_m = 0.01;
  const Mesh narrow = make_box_mesh(
      Eigen::Vector3d(kBoxSide_m - kNarrower_m, kBoxSide_m, kBoxSide_m));
  EXPECT_NEAR(opening_after(narrow, pinch, standard, "close"), plan - standard.squeeze_travel_m,
              kHeldJointTol_m);
  const SimResult r = validate_grasp(narrow, gripper(), pinch, standard, SimTests{true, false, false});
  EXPECT_EQ(r.phase("close")->outcome, Outcome::kDropped);
}

TEST(ValidateGrasp, BoundedCloseKeepsThePinchedBoxWhereItWasPlanned) {
  // The planned grasp is the one tested: the box barely moves while the pads close, and the
  // simulated contacts are at the planned ones.
  constexpr double kPlannedShiftTol_m = 1e-3;
  constexpr double kContactOffsetTol_m = 3e-3;
  const Grasp pinch = centre_pinch_with_contacts();
  const SimResult r = validate_grasp(box(), gripper(), pinch, gripper_params(Protocol::kStandard));
  EXPECT_EQ(r.outcome, Outcome::kHeld);
  EXPECT_LT(r.phase("close")->translation_m, kPlannedShiftTol_m);
  // The squeeze ended with the pads and the box at rest, not at its time limit.
  EXPECT_EQ(r.phase("close")->detail, "");
  ASSERT_EQ(r.planned_contact_offsets_m.size(), pinch.contacts.size());
  for (const double d : r.planned_contact_offsets_m) EXPECT_LT(d, kContactOffsetTol_m);
}

/// A wedge along y_O: a triangular prism whose base (`base_m` wide) lies at z = −height/2 and
/// whose apex edge lies at z = +height/2, `base_m` long.
Mesh make_wedge_mesh(double base_m, double height_m) {
  Mesh m;
  m.name = "wedge";
  for (const double y : {-0.5 * base_m, 0.5 * base_m}) {
    m.vertices.emplace_back(-0.5 * base_m, y, -0.5 * height_m);
    m.vertices.emplace_back(0.5 * base_m, y, -0.5 * height_m);
    m.vertices.emplace_back(0.0, y, 0.5 * height_m);
  }
  m.triangles = {{0, 2, 1}, {3, 4, 5}, {0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}, {2, 0, 3}, {2, 3, 5}};
  return m;
}

/// Adds to `pinch` one planned contact per pad of the gripper: `contact_at(side)` with side
/// +1 for the pad on +x of the object, −1 for the other (its link is set here).
template <class ContactAt>
void add_pad_contacts(Grasp* pinch, const ContactAt& contact_at) {
  const auto X_OL = link_poses(gripper(), pinch->q, pinch->X_OB);
  for (const Joint& joint : gripper().joints) {
    if (joint.type != JointType::kPrismatic) continue;
    const double side = X_OL[static_cast<size_t>(joint.child_link)].translation().x() > 0 ? 1 : -1;
    Contact c = contact_at(side);
    c.link = joint.child_link;
    pinch->contacts.push_back(c);
  }
}

/// The close phase of `pinch` on `mesh` (tests: lift) under `params`, and under `params`
/// without failure exits (the close judged by contact alone, run to its limits).
std::pair<PhaseResult, PhaseResult> closes_with_and_without_exits(const Mesh& mesh,
                                                                  const Grasp& pinch,
                                                                  const SimParams& params) {
  const SimTests lift_only{true, false, false};
  SimParams no_exits = params;
  no_exits.exit_on_failure = false;
  const SimResult with = validate_grasp(mesh, gripper(), pinch, params, lift_only);
  const SimResult without = validate_grasp(mesh, gripper(), pinch, no_exits, lift_only);
  const PhaseResult* a = with.phase("close");
  const PhaseResult* b = without.phase("close");
  if (a == nullptr || b == nullptr) throw std::runtime_error("no close phase");
  return {*a, *b};
}

TEST(ValidateGrasp, BoundedCloseEndsOnceTheSqueezedOutObjectLeavesTheHand) {
  // A wedge, apex toward the palm, pinched on its sloped faces without friction: the pads'
  // pushes along the face normals squeeze it out of the hand, away from the palm (gravity is
  // off while closing). The close ends once it has touched no link for no_contact_exit_time_s,
  // with the outcome of a close that runs to its time limit, and sooner.
  constexpr double kWedgeBase_m = 0.05;
  constexpr double kWedgeHeight_m = 0.05;
  const Mesh wedge = make_wedge_mesh(kWedgeBase_m, kWedgeHeight_m);
  const double half_width = 0.25 * kWedgeBase_m;  // at z = 0, half way up
  Grasp pinch = test::top_down_pinch(gripper(), Eigen::Vector3d::Zero(), half_width, kOpenGripper_m);
  add_pad_contacts(&pinch, [&](double side) {
    Contact c;
    c.p_O = Eigen::Vector3d(side * half_width, 0, 0);
    c.n_O = Eigen::Vector3d(side * kWedgeHeight_m, 0, 0.5 * kWedgeBase_m).normalized();
    return c;
  });
  SimParams params = gripper_params(Protocol::kStandard);
  params.contact.mu = 0.0;
  // Limits wide enough that the wedge leaves contact before it is off its planned pose.
  params.held_translation_m = kWedgeHeight_m;
  params.held_rotation_rad = 0.5 * M_PI;
  const auto [close, full_close] = closes_with_and_without_exits(wedge, pinch, params);
  EXPECT_GT(close.max_contact_count, 0);
  EXPECT_EQ(close.outcome, Outcome::kDropped);
  EXPECT_EQ(close.detail, "squeeze, out of contact");
  EXPECT_EQ(full_close.outcome, Outcome::kDropped);
  EXPECT_LT(close.steps, full_close.steps);
}

TEST(ValidateGrasp, BoundedCloseFailsAnObjectTurnedOffItsPlannedPose) {
  // A square prism turned 3° about the approach axis, pinched on two opposite vertical edges
  // with little friction: the pads' pushes form a couple that turns it until its faces lie
  // flat against the pads, ~4° within the 1 mm squeeze travel. The bounded close holds the
  // object to its planned pose: past the turn limit (1° here, 15° by default) it is slipped
  // in close, at once, where a close judged by contact alone (no failure exits) calls the
  // turned object held.
  constexpr double kSide_m = 0.05;
  constexpr double kPlannedTurn_rad = 3.0 * M_PI / 180.0;
  constexpr double kTurnLimit_rad = 1.0 * M_PI / 180.0;
  Mesh prism = make_box_mesh(Eigen::Vector3d::Constant(kSide_m));
  const Eigen::Matrix3d R = Eigen::AngleAxisd(kPlannedTurn_rad, Eigen::Vector3d::UnitZ()).matrix();
  for (Eigen::Vector3d& v : prism.vertices) v = R * v;
  double half_width = 0.0;
  for (const Eigen::Vector3d& v : prism.vertices) half_width = std::max(half_width, v.x());
  Grasp pinch =
      test::top_down_pinch(gripper(), Eigen::Vector3d::Zero(), half_width, kOpenGripper_m);
  add_pad_contacts(&pinch, [&](double side) {
    Contact c;  // on the vertical edge the pad meets
    for (const Eigen::Vector3d& v : prism.vertices)
      if (side * v.x() > half_width - 1e-9) c.p_O = Eigen::Vector3d(v.x(), v.y(), 0.0);
    c.n_O = Eigen::Vector3d(side, 0, 0);
    return c;
  });
  constexpr double kSlipperyMu = 0.1;
  SimParams params = gripper_params(Protocol::kStandard);
  params.contact.mu = kSlipperyMu;
  params.held_rotation_rad = kTurnLimit_rad;
  const auto [close, turned_close] = closes_with_and_without_exits(prism, pinch, params);
  EXPECT_EQ(close.outcome, Outcome::kSlipped);
  EXPECT_EQ(close.detail, "moved off the plan");
  EXPECT_GE(close.rotation_rad, kTurnLimit_rad);
  EXPECT_EQ(turned_close.outcome, Outcome::kHeld);
  EXPECT_GE(turned_close.rotation_rad, kTurnLimit_rad);
  EXPECT_LT(close.steps, turned_close.steps);
}

TEST(ValidateGrasp, FlagsAPreshapeHandPlacedIntoTheObject) {
  const SimTests lift_only{true, false, false};
  const SimResult clear = validate_grasp(box(), gripper(), centre_pinch(), gripper_params(), lift_only);
  EXPECT_FALSE(clear.preshape_overlap);
  // GCP 1 cm off the centre along x with the pads 3 cm from it: one pad starts 5 mm inside.
  constexpr double kOffCentre_m = 0.01;
  constexpr double kNarrowPreshape_m = 0.03;
  const Grasp into = test::top_down_pinch(gripper(), Eigen::Vector3d(kOffCentre_m, 0, 0),
                                          0.5 * kBoxSide_m - kOffCentre_m, kNarrowPreshape_m);
  const SimResult r = validate_grasp(box(), gripper(), into, gripper_params(), lift_only);
  EXPECT_TRUE(r.preshape_overlap);
  const PhaseResult* settle = r.phase("settle");
  ASSERT_NE(settle, nullptr);
  EXPECT_GT(settle->translation_m, SimParams{}.settle_shift_tolerance_m);
}

TEST(ValidateGrasp, PinchWithoutFrictionDrops) {
  SimParams params = gripper_params(Protocol::kThorough);
  params.contact.mu = 0.0;
  const SimResult r = validate_grasp(box(), gripper(), centre_pinch(), params);
  EXPECT_EQ(r.outcome, Outcome::kDropped);
  // The quick protocol stops the lift once the box is 2 cm down, still between the pads.
  SimParams quick = gripper_params(Protocol::kQuick);
  quick.contact.mu = 0.0;
  const SimResult q = validate_grasp(box(), gripper(), centre_pinch(), quick);
  EXPECT_EQ(q.outcome, Outcome::kSlipped);
  ASSERT_NE(q.phase("lift"), nullptr);
  EXPECT_LT(q.phase("lift")->steps, r.phase("lift")->steps);
}

TEST(ValidateGrasp, FingersOneCentimetreShortOfTheFacesDrop) {
  const SimResult r =
      validate_grasp(box(), gripper(), centre_pinch(kShortOfFaces_m), gripper_params());
  EXPECT_EQ(r.outcome, Outcome::kDropped);
  const PhaseResult* close = r.phase("close");
  ASSERT_NE(close, nullptr);
  EXPECT_FALSE(close->in_contact);
}

TEST(ValidateGrasp, HeavyBoxSlipsWhenFrictionFromTheGripIsBelowItsWeightOnly) {
  SimParams params = gripper_params();
  params.mass_kg = kHeavyBox_kg;
  const SimTests lift_only{true, false, false};
  params.effort_scale = kWeakMotors;
  const SimResult weak = validate_grasp(box(), gripper(), centre_pinch(), params, lift_only);
  EXPECT_NE(weak.outcome, Outcome::kHeld);
  EXPECT_NE(weak.outcome, Outcome::kUnstable);
  const PhaseResult* lift = weak.phase("lift");
  ASSERT_NE(lift, nullptr);
  EXPECT_GT(lift->max_translation_m, params.held_translation_m);
  params.effort_scale = kStrongMotors;
  const SimResult strong = validate_grasp(box(), gripper(), centre_pinch(), params, lift_only);
  EXPECT_EQ(strong.outcome, Outcome::kHeld);
}

TEST(ValidateGrasp, GripForceFollowsTheWeightUpToTheMotorsAndStillHolds) {
  // The pads press the box with squeeze_weight_factor · m·g / μ while that is below their
  // URDF effort, and with the effort limit otherwise or when the factor is 0.
  const SimTests lift_only{true, false, false};
  const int j = find_joint(gripper(), "left_finger_joint");
  const auto lift_grip_N = [&](const SimResult& r) {
    const PhaseResult* lift = r.phase("lift");
    return lift ? std::abs(lift->joint_efforts[static_cast<size_t>(j)]) : 0.0;
  };
  // The planned contacts: one on each pad (a prismatic joint's lever does not depend on where).
  Grasp pinch = centre_pinch();
  const auto X_OL = link_poses(gripper(), pinch.q, pinch.X_OB);
  for (const Joint& joint : gripper().joints)
    if (joint.type == JointType::kPrismatic) {
      Contact c;
      c.link = joint.child_link;
      c.p_O = X_OL[static_cast<size_t>(c.link)].translation();
      pinch.contacts.push_back(c);
    }
  ASSERT_EQ(pinch.contacts.size(), 2u);
  SimParams params = gripper_params();
  ASSERT_GT(params.squeeze_weight_factor, 0.0);
  const SimResult light = validate_grasp(box(), gripper(), pinch, params, lift_only);
  EXPECT_EQ(light.outcome, Outcome::kHeld);
  // Two pads, each pressing with the weight-scaled force, on the master's pooled drive.
  const double weight_grip_N = 2.0 * params.squeeze_weight_factor * light.object.mass_kg *
                               params.gravity_mps2 / params.contact.mu;
  params.squeeze_weight_factor = 0.0;
  const SimResult full = validate_grasp(box(), gripper(), pinch, params, lift_only);
  EXPECT_EQ(full.outcome, Outcome::kHeld);
  ASSERT_LT(weight_grip_N, 0.5 * lift_grip_N(full)) << "the box must be light for this gripper";
  EXPECT_NEAR(lift_grip_N(light), weight_grip_N, kGripForceRelTol * weight_grip_N);
  // A heavy box gets the full efforts, with or without the factor.
  params.mass_kg = kHeavyBox_kg;
  const SimResult heavy_full = validate_grasp(box(), gripper(), pinch, params, lift_only);
  params.squeeze_weight_factor = SimParams{}.squeeze_weight_factor;
  const SimResult heavy = validate_grasp(box(), gripper(), pinch, params, lift_only);
  EXPECT_EQ(heavy.outcome, Outcome::kHeld);
  EXPECT_NEAR(lift_grip_N(heavy), lift_grip_N(heavy_full),
              kGripForceRelTol * lift_grip_N(heavy_full));
}

TEST(ValidateGrasp, SamePlanAndParametersGiveIdenticalResults) {
  const SimTests tests{true, true, false};
  const SimResult a = validate_grasp(box(), gripper(), centre_pinch(), gripper_params(), tests);
  const SimResult b = validate_grasp(box(), gripper(), centre_pinch(), gripper_params(), tests);
  ASSERT_EQ(a.phases.size(), b.phases.size());
  EXPECT_EQ(a.outcome, b.outcome);
  for (size_t k = 0; k < a.phases.size(); ++k) {
    const PhaseResult& p = a.phases[k];
    const PhaseResult& q = b.phases[k];
    EXPECT_EQ(p.outcome, q.outcome) << p.name;
    EXPECT_EQ(p.translation_m, q.translation_m) << p.name;
    EXPECT_EQ(p.rotation_rad, q.rotation_rad) << p.name;
    EXPECT_EQ(p.max_penetration_m, q.max_penetration_m) << p.name;
    EXPECT_EQ(p.contact_count, q.contact_count) << p.name;
    EXPECT_EQ(p.joint_efforts, q.joint_efforts) << p.name;
    EXPECT_EQ(p.steps, q.steps) << p.name;
  }
}

TEST(ValidateGrasp, HookSeesEveryPhaseEndWithAllLinkPoses) {
  std::vector<std::string> phases;
  const SimTests tests{true, false, false};
  validate_grasp(box(), gripper(), centre_pinch(), gripper_params(), tests,
                 [&](const PhaseSnapshot& s) {
                   EXPECT_TRUE(s.phase_end) << "no trace samples unless asked for";
                   phases.push_back(s.phase);
                   EXPECT_EQ(s.X_WL.size(), gripper().links.size());
                   EXPECT_EQ(s.q.size(), static_cast<Eigen::Index>(gripper().joints.size()));
                 });
  EXPECT_EQ(phases, (std::vector<std::string>{"settle", "close", "lift"}));
}

TEST(ValidateGrasp, TraceSamplesFollowTheObjectAndEachPhaseEndsAtItsOutcome) {
  constexpr double kTraceInterval_s = 0.1;
  SimParams params = gripper_params();
  params.trace_interval_s = kTraceInterval_s;
  std::vector<PhaseSnapshot> seen;
  const SimTests tests{true, false, false};
  const SimResult r = validate_grasp(box(), gripper(), centre_pinch(), params, tests,
                                     [&](const PhaseSnapshot& s) { seen.push_back(s); });
  int lift_samples = 0;
  for (size_t i = 0; i < seen.size(); ++i) {
    if (i > 0) {
      EXPECT_GE(seen[i].sim_time_s, seen[i - 1].sim_time_s);
    }
    if (seen[i].phase == "lift" && !seen[i].phase_end) ++lift_samples;
  }
  const PhaseResult* lift = r.phase("lift");
  ASSERT_NE(lift, nullptr);
  EXPECT_EQ(lift_samples,
            lift->steps / static_cast<int>(std::lround(kTraceInterval_s / params.time_step_s)));
  // The lift raises the box 10 cm; in the hand it stays put, touching both pads throughout.
  for (const PhaseSnapshot& s : seen) {
    if (s.phase != "lift") continue;
    EXPECT_LT(s.object_shift_m, params.held_translation_m) << s.sim_time_s;
    EXPECT_GE(s.contact_count, 2) << s.sim_time_s;
  }
  // Each phase's last snapshot measures what its outcome measured.
  for (const PhaseResult& p : r.phases) {
    const auto end = std::find_if(seen.begin(), seen.end(), [&](const PhaseSnapshot& s) {
      return s.phase_end && s.phase == p.name;
    });
    ASSERT_NE(end, seen.end()) << p.name;
    EXPECT_NEAR(end->object_shift_m, p.translation_m, 1e-12) << p.name;
    EXPECT_NEAR(end->object_turn_rad, p.rotation_rad, 1e-12) << p.name;
  }
}

TEST(ValidateGrasp, WorldFrameTurnsTheApproachDownAndTheHandRisesDuringLift) {
  const Grasp grasp = centre_pinch();
  Eigen::Isometry3d X_WB_close, X_WB_lift;
  const SimTests tests{true, false, false};
  const size_t root = static_cast<size_t>(gripper().root_link);
  const SimResult r = validate_grasp(box(), gripper(), grasp, gripper_params(), tests,
                                     [&](const PhaseSnapshot& s) {
                                       if (s.phase == "close") X_WB_close = s.X_WL[root];
                                       if (s.phase == "lift") X_WB_lift = s.X_WL[root];
                                     });
  // Approach (+z of the GCP) along −z of the world.
  const Eigen::Vector3d z_G = (r.X_WO * grasp.X_OG).linear().col(2);
  EXPECT_NEAR(z_G.z(), -1.0, 1e-12);
  EXPECT_NEAR((X_WB_lift.translation() - X_WB_close.translation()).z(),
              SimParams{}.lift_height_m, 1e-3);
}

TEST(ValidateGrasp, BoxInertiaIsTheSolidBoxs) {
  const Eigen::Vector3d size(0.04, 0.06, 0.1);
  const Mesh mesh = make_box_mesh(size);
  SimParams params;
  params.mass_kg = 0.3;
  const SimResult r = validate_grasp(mesh, gripper(), centre_pinch(kShortOfFaces_m), params,
                                     SimTests{false, false, false});
  const double m = *params.mass_kg;
  std::vector<double> expected = {m / 12 * (size.y() * size.y() + size.z() * size.z()),
                                  m / 12 * (size.x() * size.x() + size.z() * size.z()),
                                  m / 12 * (size.x() * size.x() + size.y() * size.y())};
  std::vector<double> got(r.object.principal_inertia_kgm2.data(),
                          r.object.principal_inertia_kgm2.data() + 3);
  std::sort(expected.begin(), expected.end());
  std::sort(got.begin(), got.end());
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(got[a], expected[a], kInertiaRelTol * expected[a]);
  EXPECT_EQ(r.object.shape, ObjectShape::kConvexHull);
  EXPECT_TRUE(r.object.closed);
}

/// A box of side `side_m` without its top face (an open, non-watertight mesh).
Mesh open_box(double side_m) {
  Mesh mesh = make_box_mesh(Eigen::Vector3d::Constant(side_m));
  std::vector<Eigen::Vector3i> kept;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    bool top = true;
    for (int i = 0; i < 3; ++i) top = top && mesh.vertices[t[i]].z() > 0.49 * side_m;
    if (!top) kept.push_back(t);
  }
  mesh.triangles = kept;
  return mesh;
}

TEST(ValidateGrasp, OpenMeshMassIsAShellOfItsSurfaceAtMostItsHull) {
  constexpr double kMassRelTol = 1e-9;
  const SimParams params;
  // 20 cm open box: five faces × 1 cm shell = 2 l, less than the hull's 8 l.
  const double big_m = 0.2;
  const SimResult big = validate_grasp(open_box(big_m), gripper(), centre_pinch(kShortOfFaces_m),
                                       params, SimTests{false, false, false});
  EXPECT_FALSE(big.object.closed);
  const double shell_kg = params.density_kgm3 * 5 * big_m * big_m * params.open_mesh_shell_m;
  EXPECT_NEAR(big.object.mass_kg, shell_kg, kMassRelTol * shell_kg);
  // 2 cm open box: the shell (20 cm³) would exceed the hull (8 cm³): the hull's volume.
  const double small_m = 0.02;
  const SimResult small = validate_grasp(open_box(small_m), gripper(),
                                         centre_pinch(kShortOfFaces_m), params,
                                         SimTests{false, false, false});
  const double hull_kg = params.density_kgm3 * std::pow(small_m, 3);
  EXPECT_NEAR(small.object.mass_kg, hull_kg, 1e-6 * hull_kg);
}

TEST(ValidateGrasp, ThrowsWhenTheJointVectorsDoNotFitTheHand) {
  Grasp g = centre_pinch();
  g.q.resize(1);
  EXPECT_THROW(validate_grasp(box(), gripper(), g, SimParams{}), std::invalid_argument);
}

TEST(SimTestsFromString, ParsesSubsetsAndRejectsUnknownNames) {
  const SimTests t = sim_tests_from_string("shake,lift");
  EXPECT_TRUE(t.lift);
  EXPECT_TRUE(t.shake);
  EXPECT_FALSE(t.gravity6);
  EXPECT_EQ(to_string(t), "lift,shake");
  EXPECT_THROW(sim_tests_from_string("lift,wobble"), std::invalid_argument);
  EXPECT_THROW(sim_tests_from_string(""), std::invalid_argument);
}

TEST(ObjectShapeFromString, RoundTripsEveryShape) {
  for (ObjectShape s : {ObjectShape::kAuto, ObjectShape::kConvexHull, ObjectShape::kDecomposition,
                        ObjectShape::kGImpact})
    EXPECT_EQ(parse_object_shape(to_string(s)), s);
  EXPECT_THROW(parse_object_shape("vhacd"), std::invalid_argument);
}

TEST(ProtocolFromString, RoundTripsEveryProtocol) {
  for (Protocol p : {Protocol::kQuick, Protocol::kThorough, Protocol::kStandard})
    EXPECT_EQ(parse_protocol(to_string(p)), p);
  EXPECT_THROW(parse_protocol("medium"), std::invalid_argument);
  EXPECT_THROW(parse_protocol("fast"), std::invalid_argument);  // dropped: standard is cheaper
}

/// "name=value;" for every field of a parameter struct, nested ones recursively: two structs
/// with the same text have the same values.
class FieldText {
 public:
  template <typename T>
  void Visit(const NameValuePair<T>& nvp) {
    text_ += std::string(nvp.name) + "=";
    write(*nvp.value);
    text_ += ";";
  }
  template <typename T>
  static std::string of(T params) {
    FieldText archive;
    params.Serialize(&archive);
    return archive.text_;
  }

 private:
  template <typename T>
  void write(const T& value) {
    if constexpr (std::is_arithmetic_v<T>) {
      std::ostringstream out;
      out.precision(17);
      out << value;
      text_ += out.str();
    } else if constexpr (std::is_enum_v<T>) {
      text_ += std::to_string(static_cast<int>(value));
    } else if constexpr (std::is_same_v<T, std::string>) {
      text_ += value;
    } else if constexpr (std::is_same_v<T, std::optional<double>>) {
      text_ += value ? std::to_string(*value) : "unset";
    } else {
      text_ += "{" + of(value) + "}";
    }
  }
  std::string text_;
};

std::string sim_params_to_text_for_test(const SimParams& params) {
  return FieldText::of(params);
}

TEST(ApplyProtocol, StandardIsTheDefaultAndThoroughTheLongProtocol) {
  // The defaults are the standard preset, field for field.
  const SimParams defaults;
  EXPECT_EQ(defaults.protocol, Protocol::kStandard);
  EXPECT_EQ(sim_params_to_text_for_test(sim_params_for(Protocol::kStandard)),
            sim_params_to_text_for_test(defaults));
  const SimParams quick = sim_params_for(Protocol::kQuick);
  EXPECT_EQ(quick.time_step_s, 1.0 / 960.0);
  EXPECT_FALSE(quick.shake_all_axes_at_once);
  // Standard: the bounded close, quick's exits, a shorter lift at quick's peak acceleration
  // (minimum jerk: ∝ height / time²), shake and rock along all axes at once.
  const SimParams standard = sim_params_for(Protocol::kStandard);
  EXPECT_EQ(standard.protocol, Protocol::kStandard);
  constexpr double kSamePeakAccelRelTol = 0.05;
  const auto lift_accel = [](const SimParams& p) {
    return p.lift_height_m / (p.lift_time_s * p.lift_time_s);
  };
  EXPECT_LT(standard.lift_time_s, quick.lift_time_s);
  EXPECT_NEAR(lift_accel(standard) / lift_accel(quick), 1.0, kSamePeakAccelRelTol);
  // A shorter shake at quick's peak acceleration (A·ω²), one full period; quick's rock.
  const auto omega = [](double hz) { return 2.0 * M_PI * hz; };
  const auto shake_accel = [&](const SimParams& p) {
    return p.shake_amplitude_m * omega(p.shake_frequency_hz) * omega(p.shake_frequency_hz);
  };
  EXPECT_LT(standard.shake_time_s, quick.shake_time_s);
  EXPECT_NEAR(shake_accel(standard) / shake_accel(quick), 1.0, kSamePeakAccelRelTol);
  EXPECT_GE(standard.shake_frequency_hz * standard.shake_time_s, 1.0);
  EXPECT_EQ(standard.rock_angle_rad, quick.rock_angle_rad);
  EXPECT_EQ(standard.rock_frequency_hz, quick.rock_frequency_hz);
  EXPECT_EQ(standard.rock_time_s, quick.rock_time_s);
  EXPECT_GT(standard.reach_start_gap_m, 0.0);
  EXPECT_GT(standard.squeeze_travel_m, 0.0);
  EXPECT_LT(standard.squeeze_travel_m, 0.01);
  EXPECT_EQ(standard.reach_start_fraction, 0.0);
  EXPECT_TRUE(standard.shake_all_axes_at_once);
  EXPECT_TRUE(standard.exit_on_failure);
  EXPECT_EQ(quick.squeeze_travel_m, 0.0);
  EXPECT_EQ(quick.reach_start_gap_m, 0.0);
  // Thorough: the protocol's numbers before the quick preset, and no early exit.
  const SimParams t = sim_params_for(Protocol::kThorough);
  EXPECT_EQ(t.protocol, Protocol::kThorough);
  EXPECT_EQ(t.settle_time_s, 0.05);
  EXPECT_EQ(t.squeeze_max_time_s, 0.5);
  EXPECT_EQ(t.lift_height_m, 0.10);
  EXPECT_EQ(t.lift_time_s, 1.0);
  EXPECT_EQ(t.lift_hold_s, 1.0);
  EXPECT_EQ(t.shake_amplitude_m, 0.02);
  EXPECT_EQ(t.shake_frequency_hz, 2.0);
  EXPECT_EQ(t.shake_time_s, 1.0);
  EXPECT_EQ(t.rock_angle_rad, 15.0 * M_PI / 180.0);
  EXPECT_EQ(t.rock_frequency_hz, 1.0);
  EXPECT_EQ(t.rock_time_s, 1.0);
  EXPECT_EQ(t.gravity6_time_s, 1.0);
  EXPECT_EQ(t.reach_start_fraction, 0.0);
  EXPECT_FALSE(t.shake_all_axes_at_once);
  EXPECT_EQ(t.rest_exit_time_s, 0.0);
  EXPECT_FALSE(t.exit_on_failure);
  EXPECT_EQ(t.time_step_s, 1.0 / 960.0);
  EXPECT_EQ(t.solver_iterations, 50);
  EXPECT_EQ(t.contact_stiffness_Npm, 0.0);
  // Applying a preset leaves the fields it does not own.
  SimParams custom;
  custom.contact.mu = 0.3;
  custom.held_translation_m = 0.03;
  custom.time_step_s = 1.0 / 2000.0;
  apply_protocol(Protocol::kThorough, &custom);
  EXPECT_EQ(custom.time_step_s, 1.0 / 960.0);  // a preset field
  EXPECT_EQ(custom.contact.mu, 0.3);
  EXPECT_EQ(custom.held_translation_m, 0.03);
  EXPECT_EQ(custom.lift_time_s, 1.0);
}

}  // namespace
}  // namespace cordgrasp
