// Hand descriptions drafted from the URDF alone (draft_hand_description) load, follow the
// conventions and plan force-closure grasps of the shipped box and mug.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <initializer_list>
#include <iostream>
#include <set>

#include "cordgrasp/collision/bullet_hand_collider.h"
#include "cordgrasp/core/atomic_file.h"
#include "cordgrasp/core/draft_hand_description.h"
#include "cordgrasp/core/hand_conventions.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/plan_cord_grasps.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

namespace fs = std::filesystem;

constexpr int kSphereAttempts = 100;
constexpr int kThreads = 2;  // test planning's (the draft does not depend on them)
constexpr double kGcpMovedAtLeast_m = 0.005;

/// The collider `hand init` tests its GCP places with.
std::unique_ptr<HandObjectCollider> make_collider(const HandModel& hand, const Mesh& object) {
  return make_bullet_hand_collider(hand, object);
}

/// Drafts a description for `urdf` as `hand init` does (with test planning), writes it to a
/// temp file and loads it back.
HandModel draft_and_load(const std::string& urdf, const std::string& name, HandDraft* out) {
  const fs::path dir = fs::temp_directory_path() / "cordgrasp_draft_test";
  fs::create_directories(dir);
  const std::string path = (dir / (name + ".yaml")).string();
  HandDraft draft = draft_hand_description(urdf, path, {}, make_collider, kThreads);
  write_file_atomically(path, draft.yaml);
  HandModel hand = load_hand(path);
  if (out) *out = std::move(draft);
  return hand;
}

/// The cord planner finds a force-closure grasp of each shipped object named.
void expect_plans(const HandModel& hand, std::initializer_list<const char*> objects) {
  for (const char* object : objects) {
    const Mesh mesh = load_mesh(test::source_dir() + "/assets/objects/" + object + ".obj");
    auto collider = make_bullet_hand_collider(hand, mesh);
    CordParams cord;
    PlanParams plan;
    plan.time_limit_s = 600.0;  // the attempt budget decides, not the machine's speed
    plan.quality.contact.soft_finger_radius_m = hand.soft_finger_radius_m;  // as `plan` does
    const PlanResult result = plan_cord_grasps(mesh, hand, *collider, cord, plan);
    ASSERT_FALSE(result.grasps.empty())
        << hand.name << " on " << object << ": " << result.stats.attempts << " attempts, "
        << result.stats.no_contact << " no contact, " << result.stats.one_contact
        << " one contact, " << result.stats.not_force_closure << " not FC";
    EXPECT_TRUE(result.grasps.front().force_closure);
  }
}

/// The cord planner finds a force-closure grasp of the shipped box and mug.
void expect_plans_box_and_mug(const HandModel& hand) { expect_plans(hand, {"box", "mug"}); }

std::set<std::string> actor_joints(const HandModel& h) {
  std::set<std::string> out;
  for (const Actor& a : h.actors)
    for (const auto& e : a.joints)
      out.insert(h.joints[e.joint].name + (e.direction_speed > 0 ? " +" : " -"));
  return out;
}

/// Prints where the draft differs from the shipped description (for the notes).
void print_comparison(const HandModel& shipped, const HandModel& draft) {
  const auto a = actor_joints(shipped), b = actor_joints(draft);
  std::cout << shipped.name << ": actors " << shipped.actors.size() << " shipped / "
            << draft.actors.size() << " drafted;";
  for (const auto& j : a)
    if (!b.count(j)) std::cout << " only shipped: " << j << ";";
  for (const auto& j : b)
    if (!a.count(j)) std::cout << " only drafted: " << j << ";";
  const auto thumb = [](const HandModel& h) {
    return h.thumb_links.empty() ? std::string("-") : h.links[h.thumb_links.front()].name;
  };
  std::cout << " thumb " << thumb(shipped) << " / " << thumb(draft) << "\n";
}

/// The drafted palm normal lies within 10° of the shipped one (both on the same link: the
/// palm the draft finds is the link the shipped description names).
void expect_palm_normal_near_shipped(const HandModel& shipped, const HandModel& draft) {
  ASSERT_TRUE(shipped.palm_normal && draft.palm_normal);
  ASSERT_EQ(shipped.links[shipped.palm_normal->link].name,
            draft.links[draft.palm_normal->link].name);
  constexpr double kNormalTol_rad = 10.0 * M_PI / 180.0;
  const double c = shipped.palm_normal->n_L.normalized().dot(draft.palm_normal->n_L.normalized());
  EXPECT_LT(std::acos(std::clamp(c, -1.0, 1.0)), kNormalTol_rad)
      << shipped.name << ": drafted " << draft.palm_normal->n_L.transpose() << ", shipped "
      << shipped.palm_normal->n_L.transpose();
}

/// The first `count` hands of the zoo of `seed` (tools/make_hand_zoo.py) made afresh in `folder`.
::testing::AssertionResult make_zoo(const fs::path& folder, int count, int seed) {
  fs::remove_all(folder);
  const std::string cmd = std::string(CORDGRASP_PYTHON) + " " + test::source_dir() +
                          "/tools/make_hand_zoo.py --out " + folder.string() + " --count " +
                          std::to_string(count) + " --seed " + std::to_string(seed) +
                          " > /dev/null";
  if (std::system(cmd.c_str()) != 0) return ::testing::AssertionFailure() << cmd;
  return ::testing::AssertionSuccess();
}

TEST(DraftHand, NeverSeenThreeDigitClawLoadsFollowsTheConventionsAndPlans) {
  HandDraft draft;
  const HandModel hand = draft_and_load(
      test::test_data("hands/three_digit_claw/three_digit_claw.urdf"), "three_digit_claw",
      &draft);
  EXPECT_TRUE(draft.problems.empty()) << draft.problems.front();
  EXPECT_TRUE(check_hand_conventions(hand).empty());
  ASSERT_EQ(hand.actors.size(), 3u);
  ASSERT_FALSE(hand.thumb_links.empty());
  EXPECT_EQ(hand.links[hand.thumb_links.front()].name, "opposer_seg1");
  // The opposer's knuckle closes with negative motion (its axis is reversed); the digits'
  // hinges follow by <mimic>, so each actor lists its knuckle only.
  for (const Actor& a : hand.actors) {
    ASSERT_EQ(a.joints.size(), 1u) << a.name;
    const Joint& j = hand.joints[a.joints[0].joint];
    EXPECT_NE(j.name.find("_knuckle"), std::string::npos);
    EXPECT_EQ(a.joints[0].direction_speed < 0, j.name == "opposer_knuckle") << j.name;
  }
  ASSERT_TRUE(hand.palm_normal.has_value());
  EXPECT_TRUE(hand.palm_normal->n_L.isApprox(Eigen::Vector3d::UnitZ(), 1e-6))
      << hand.palm_normal->n_L.transpose();
  EXPECT_GE(draft.guesses.size(), 5u);
  expect_plans_box_and_mug(hand);
}

TEST(DraftHand, NeverSeenOpposedClawTakesItsPalmNormalFromWhereTheFingertipsMeet) {
  // Two digits and a third opposing them stand up from the palm face (-y of 'base') and curl
  // towards each other: their flexion runs across the palm, not along its normal.
  HandDraft draft;
  const HandModel hand = draft_and_load(
      test::test_data("hands/opposed_claw/opposed_claw.urdf"), "opposed_claw", &draft);
  for (const auto& p : draft.problems) ADD_FAILURE() << p;
  EXPECT_TRUE(check_hand_conventions(hand).empty());
  ASSERT_TRUE(hand.palm_normal.has_value());
  ASSERT_EQ(hand.links[hand.palm_normal->link].name, "base");
  constexpr double kNormalTol_rad = 10.0 * M_PI / 180.0;
  EXPECT_LT(std::acos(hand.palm_normal->n_L.normalized().dot(-Eigen::Vector3d::UnitY())),
            kNormalTol_rad)
      << hand.palm_normal->n_L.transpose();
  // The GCP lies in front of the palm face (y = -0.015), its +z along the palm normal.
  const Eigen::Isometry3d& X_LG = hand.gcp.X_LG;
  EXPECT_LT(X_LG.translation().y(), -0.015);
  EXPECT_GT(X_LG.linear().col(2).dot(-Eigen::Vector3d::UnitY()), std::cos(kNormalTol_rad));
  // The lone digit opposing the other two is the thumb; every digit closes with its knuckle
  // (the tip joints follow by <mimic>), positive motion curling it across the palm.
  ASSERT_FALSE(hand.thumb_links.empty());
  EXPECT_EQ(hand.links[hand.thumb_links.front()].name, "right_proximal");
  ASSERT_EQ(hand.actors.size(), 3u);
  for (const Actor& a : hand.actors) {
    ASSERT_EQ(a.joints.size(), 1u) << a.name;
    EXPECT_NE(hand.joints[a.joints[0].joint].name.find("_flex"), std::string::npos);
    EXPECT_GT(a.joints[0].direction_speed, 0.0) << a.name;
  }
  bool evidence = false;
  for (const DraftGuess& g : draft.guesses)
    evidence = evidence || (g.what == "palm normal" &&
                            g.why.find("where the fingertips meet") != std::string::npos);
  EXPECT_TRUE(evidence) << "the palm normal guess names its witness";
  // The mug (8 cm, 11 cm with its handle) does not fit between digits 9 cm apart that open by
  // 6° only; the box and the cylinder do.
  expect_plans(hand, {"box", "long_cylinder"});
}

TEST(DraftHand, ShippedPrimitiveHandsDraftsPlan) {
  for (const char* name : {"cordgrasp_sah", "parallel_gripper"}) {
    const HandModel shipped = load_hand(name);
    HandDraft draft;
    const HandModel hand = draft_and_load(shipped.urdf_path, name, &draft);
    for (const auto& p : draft.problems) ADD_FAILURE() << p;
    print_comparison(shipped, hand);
    expect_palm_normal_near_shipped(shipped, hand);
    expect_plans_box_and_mug(hand);
  }
}

TEST(DraftHand, FingersWithTwoSidedLimitsFlexTowardsTheThumbsSideAndPlan) {
  // Hand 6 of the seed-1 zoo (tools/make_hand_zoo.py, made here): a human layout whose two
  // fingers' joints all have limits of ±90°, so no limit tells which way they flex. They flex
  // towards +x of their own frames (the zoo's convention: positive about +y), the side of the
  // palm the thumb stands on.
  const fs::path zoo = fs::temp_directory_path() / "cordgrasp_draft_two_sided_test";
  ASSERT_TRUE(make_zoo(zoo, 7, 1));
  const std::string urdf = (zoo / "hand_06" / "hand_06.urdf").string();
  const HandDraft draft = draft_hand_description(urdf, (zoo / "hand_06.yaml").string());
  EXPECT_TRUE(draft.problems.empty()) << draft.problems.front();
  const std::set<std::string> closing = actor_joints(draft.hand);
  for (const char* joint : {"f0_j0 +", "f1_j0 +", "f1_j1 +"})
    EXPECT_TRUE(closing.count(joint)) << joint;
  const auto normal_guess =
      std::find_if(draft.guesses.begin(), draft.guesses.end(),
                   [](const DraftGuess& g) { return g.what == "palm normal"; });
  ASSERT_NE(normal_guess, draft.guesses.end());
  EXPECT_NE(normal_guess->why.find("thumb's side"), std::string::npos) << normal_guess->why;
  write_file_atomically((zoo / "hand_06.yaml").string(), draft.yaml);
  expect_plans(load_hand((zoo / "hand_06.yaml").string()), {"sphere"});
}

TEST(DraftHand, TestPlanningMovesAGcpThatPlansNothingToOneThatPlans) {
  // Hand 3 of the seed-1 zoo (tools/make_hand_zoo.py, made here): a human layout with one-joint
  // fingers of 4.5 cm whose fingertips meet 23 mm in front of a 7 x 8.5 cm palm. At the drafted
  // place between the thumb tip and the fingertips its GCP plans no force-closure grasp of the
  // shipped sphere in 100 attempts.
  const fs::path zoo = fs::temp_directory_path() / "cordgrasp_draft_gcp_test";
  ASSERT_TRUE(make_zoo(zoo, 4, 1));
  const std::string urdf = (zoo / "hand_03" / "hand_03.urdf").string();
  const HandDraft plain = draft_hand_description(urdf, (zoo / "plain.yaml").string());
  HandDraft tested;
  const HandModel hand = draft_and_load(urdf, "hand_03_tested", &tested);
  EXPECT_TRUE(tested.problems.empty());
  // The description written holds the place chosen, and the guess says why.
  EXPECT_TRUE(hand.gcp.X_LG.isApprox(tested.hand.gcp.X_LG, 1e-5));
  const double moved_m =
      (tested.hand.gcp.X_LG.translation() - plain.hand.gcp.X_LG.translation()).norm();
  EXPECT_GT(moved_m, kGcpMovedAtLeast_m);
  const auto gcp_guess = std::find_if(tested.guesses.begin(), tested.guesses.end(),
                                      [](const DraftGuess& g) { return g.what == "gcp"; });
  ASSERT_NE(gcp_guess, tested.guesses.end());
  EXPECT_NE(gcp_guess->why.find("test planning"), std::string::npos) << gcp_guess->why;
  // One thread drafts the same description.
  EXPECT_EQ(draft_hand_description(urdf, (zoo / "one_thread.yaml").string(), {}, make_collider, 1)
                .hand.gcp.X_LG.translation(),
            tested.hand.gcp.X_LG.translation());

  const Mesh sphere = load_mesh(test::source_dir() + "/assets/objects/sphere.obj");
  auto plan_sphere = [&](const HandModel& h) {
    auto collider = make_bullet_hand_collider(h, sphere);
    PlanParams plan;
    plan.max_attempts = kSphereAttempts;
    plan.fallback_attempts = 0;  // the regions' placement at the GCP, as test planning judges
    plan.time_limit_s = 600.0;   // the attempt budget decides, not the machine's speed
    return plan_cord_grasps(sphere, h, *collider, CordParams{}, plan).stats;
  };
  EXPECT_EQ(plan_sphere(plain.hand).force_closure, 0);
  EXPECT_GT(plan_sphere(hand).force_closure, 0);
}

TEST(DraftHandDataset, EveryStagedHandDraftsAndPlans) {
  CORDGRASP_REQUIRE_SHARED_DATA();
  for (const char* name : {"schunk_sah", "icub_right_hand", "armar3_right_hand", "allegro_right",
                           "panda_hand", "barrett_bh282"}) {
    SCOPED_TRACE(name);
    const HandModel shipped = load_hand(name);
    HandDraft draft;
    const HandModel hand = draft_and_load(shipped.urdf_path, name, &draft);
    for (const auto& p : draft.problems) ADD_FAILURE() << p;
    print_comparison(shipped, hand);
    expect_palm_normal_near_shipped(shipped, hand);
    expect_plans_box_and_mug(hand);
  }
}

}  // namespace
}  // namespace cordgrasp
