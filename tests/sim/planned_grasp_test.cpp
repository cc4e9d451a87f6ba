// Physics validation of grasps from the cord planner (docs/physics.md): the default hand's first
// force-closure grasp on the shipped box is tested as planned and holds, squeezed either way;
// planned short of the box, its fingers end the close without pressing it; quick's squeeze holds
// the cylinder only after moving it; on every shipped object the simulation stays finite and
// stable.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "cordgrasp/collision/bullet_hand_collider.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/kinematics.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/plan_cord_grasps.h"
#include "cordgrasp/sim/grasp_validation.h"
#include "cordgrasp/sim/validate_grasp.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

constexpr std::uint64_t kSeed = 1;
constexpr double kPlanTimeLimit_s = 10.0;  ///< a cap the planner never needs on these objects
/// Deepest finger–object penetration accepted as "not blown up" [m]: five times the 1 mm
/// the solver defaults keep on the test gripper; a blow-up goes far deeper.
constexpr double kMaxPenetration_m = 5e-3;
/// Largest joint effort accepted [N·m or N]: a finite bound well above every shipped hand's
/// effort limits (≤ 2 N·m for the SAH-like hand); NaN fails it too.
constexpr double kMaxEffort = 1e3;

const HandModel& default_hand() {
  static const HandModel hand = load_hand(default_hand_name());
  return hand;
}

std::string shipped_object(const std::string& name) {
  return test::source_dir() + "/assets/objects/" + name + ".obj";
}

/// First force-closure grasp of the seeded cord planner (empty q when there is none).
Grasp first_planned_grasp(const Mesh& mesh, const HandModel& hand) {
  auto collider = make_bullet_hand_collider(hand, mesh);
  PlanParams params;
  params.seed = kSeed;
  params.time_limit_s = kPlanTimeLimit_s;
  CordParams cord;
  cord.seed = kSeed;
  const PlanResult plan = plan_cord_grasps(mesh, hand, *collider, cord, params);
  return plan.grasps.empty() ? Grasp{} : plan.grasps.front();
}

/// Default simulation parameters with the planner's friction model (one source of truth).
SimParams planner_contact_params() {
  SimParams params;
  params.contact = PlanParams{}.quality.contact;
  return params;
}

TEST(ValidatePlannedGrasp, ForceClosureSahGraspOnTheBoxIsTestedAsPlannedAndHolds) {
  // The default protocol tests the grasp that was planned: the box barely moves while the
  // hand closes, the simulated contacts are at the planned ones, and it holds.
  constexpr double kPlannedShift_m = 5e-3;
  constexpr double kContactOffset_m = 5e-3;
  const Mesh mesh = load_mesh(shipped_object("box"));
  const Grasp grasp = first_planned_grasp(mesh, default_hand());
  ASSERT_GT(grasp.q.size(), 0) << "no force-closure grasp planned";
  ASSERT_TRUE(grasp.force_closure);
  const SimTests lift_shake{true, true, false};
  const SimResult r =
      validate_grasp(mesh, default_hand(), grasp, planner_contact_params(), lift_shake);
  EXPECT_EQ(r.outcome, Outcome::kHeld) << to_string(r.outcome);
  for (const char* name : {"close", "lift", "shake"}) {
    const PhaseResult* p = r.phase(name);
    ASSERT_NE(p, nullptr) << name;
    EXPECT_EQ(p->outcome, Outcome::kHeld) << name << " " << p->detail;
    EXPECT_TRUE(p->in_contact) << name;
  }
  EXPECT_LT(r.phase("close")->translation_m, kPlannedShift_m);
  // The fingers press the box with their squeeze effort when the lift begins.
  EXPECT_GE(r.phase("close")->squeeze_effort_ratio, kPressingEffortRatio);
  EXPECT_EQ(r.phase("settle")->squeeze_effort_ratio, 0.0);  // before the close
  ASSERT_EQ(r.planned_contact_offsets_m.size(), grasp.contacts.size());
  for (const double d : r.planned_contact_offsets_m) EXPECT_LT(d, kContactOffset_m);
  const PhaseResult& shake = *r.phase("shake");
  EXPECT_LT(shake.translation_m, SimParams{}.held_translation_m);
  EXPECT_LT(shake.rotation_rad, SimParams{}.held_rotation_rad);
  EXPECT_LT(shake.max_penetration_m, kMaxPenetration_m);
}

TEST(ValidatePlannedGrasp, FingersPlannedShortOfTheBoxEndTheCloseWithoutPressingIt) {
  // The same grasp with every finger's planned value a few millimetres short of the box: the
  // bounded squeeze (1 mm past the plan) ends without load, and sim.json's ratio says so.
  constexpr double kShort_m = 4e-3;  // at the finger's lever, beyond the squeeze's travel
  const Mesh mesh = load_mesh(shipped_object("box"));
  Grasp grasp = first_planned_grasp(mesh, default_hand());
  ASSERT_GT(grasp.q.size(), 0) << "no force-closure grasp planned";
  const HandModel& hand = default_hand();
  const Eigen::VectorXd lever = contact_levers(hand, grasp.q, grasp.X_OB, grasp.contacts);
  for (const Actor& actor : hand.actors)
    for (const auto& e : actor.joints)
      if (lever[e.joint] > 0.0)
        grasp.q[e.joint] -= std::copysign(kShort_m / lever[e.joint], e.direction_speed);
  grasp.q = clamp_to_limits(hand, apply_couplings(hand, grasp.q));
  const SimResult r =
      validate_grasp(mesh, hand, grasp, planner_contact_params(), SimTests{true, false, false});
  const PhaseResult* close = r.phase("close");
  ASSERT_NE(close, nullptr);
  EXPECT_LT(close->squeeze_effort_ratio, kPressingEffortRatio) << close->detail;
  EXPECT_NE(r.outcome, Outcome::kHeld);
}

TEST(ValidatePlannedGrasp, QuickSqueezeHoldsTheCylinderGraspOnlyAfterMovingIt) {
  // Quick's squeeze (0.5 rad past the plan until its time limit) holds the first cylinder
  // grasp, but a grasp it made itself: the cylinder has moved centimetres while closing.
  constexpr double kReseated_m = 0.01;
  const Mesh mesh = load_mesh(shipped_object("long_cylinder"));
  const Grasp grasp = first_planned_grasp(mesh, default_hand());
  ASSERT_GT(grasp.q.size(), 0) << "no force-closure grasp planned";
  SimParams params = planner_contact_params();
  apply_protocol(Protocol::kQuick, &params);
  const SimResult r =
      validate_grasp(mesh, default_hand(), grasp, params, SimTests{true, true, false});
  EXPECT_EQ(r.outcome, Outcome::kHeld) << to_string(r.outcome);
  ASSERT_NE(r.phase("close"), nullptr);
  EXPECT_GT(r.phase("close")->translation_m, kReseated_m);
}

TEST(ValidatePlannedGrasp, DefaultHandStaysStableOnEveryShippedObject) {
  const auto objects = test::files_in(test::source_dir() + "/assets/objects", ".obj");
  ASSERT_GE(objects.size(), 10u);
  for (const std::string& path : objects) {
    const Mesh mesh = load_mesh(path);
    const Grasp grasp = first_planned_grasp(mesh, default_hand());
    ASSERT_GT(grasp.q.size(), 0) << path << ": no force-closure grasp planned";
    const SimResult r = validate_grasp(mesh, default_hand(), grasp, planner_contact_params(),
                                       SimTests{true, true, true});
    EXPECT_NE(r.outcome, Outcome::kUnstable) << path;
    for (const PhaseResult& p : r.phases) {
      if (p.outcome == Outcome::kNotRun) continue;
      EXPECT_NE(p.outcome, Outcome::kUnstable) << path << " " << p.name;
      EXPECT_TRUE(std::isfinite(p.translation_m)) << path << " " << p.name;
      EXPECT_TRUE(std::isfinite(p.rotation_rad)) << path << " " << p.name;
      EXPECT_LT(p.max_penetration_m, kMaxPenetration_m) << path << " " << p.name;
      for (double effort : p.joint_efforts)
        EXPECT_LT(std::abs(effort), kMaxEffort) << path << " " << p.name;
      EXPECT_GT(p.steps, 0) << path << " " << p.name;
    }
  }
}

}  // namespace
}  // namespace cordgrasp
