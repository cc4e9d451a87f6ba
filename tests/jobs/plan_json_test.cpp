// plan.json round trip (tools/jobs/include/cordgrasp/jobs/plan_json.h).
#include "cordgrasp/jobs/plan_json.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <fstream>

#include "cordgrasp/core/error.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/jobs/plan_job.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() /
          ("cordgrasp_plan_json_test_" + std::to_string(::getpid()) + "_" + name))
      .string();
}

PlanDocument sample_plan(const HandModel& hand) {
  PlanDocument doc;
  doc.cordgrasp_version = "0.1.0";
  doc.hand_name = hand.name;
  doc.hand_path = "/abs/hand.yaml";
  doc.urdf_path = "/abs/hand.urdf";
  doc.object_path = "/abs/box.obj";
  doc.object_name = "box";
  doc.object_triangles = 12;
  doc.planner = PlannerKind::kCord;
  doc.params.seed = 7;
  doc.params.quality.contact.mu = 0.7;
  doc.params.quality.contact.soft_finger_radius_m = 0.004;
  doc.palm_width_m = 0.085;
  CordParams cord;
  cord.seed = 7;
  cord.xi_min_m = 0.02;       // fields the old plan.json left out: the replay needs them
  cord.eps_len_m = 2e-9;
  cord.xor_backend = XorBackend::kClipper;
  cord.sphere_sequence = SphereSequence::kFibonacci;
  cord.side_cord_policy = SideCordPolicy::kShrink;
  doc.cord = cord;
  doc.object_scale = 2.5;
  doc.stats.attempts = 3;
  doc.stats.force_closure = 1;
  doc.stats.first_force_closure_s = 0.25;
  Grasp g;
  g.X_OB = Eigen::Translation3d(0.1, -0.2, 0.3) *
           Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized());
  g.X_OG = Eigen::Translation3d(0.0, 0.0, 0.05) * Eigen::AngleAxisd(2.5, Eigen::Vector3d::UnitY());
  g.q = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(hand.joints.size()));
  g.q_preshape = g.q;
  for (size_t j = 0; j < hand.joints.size(); ++j)
    if (hand.joints[j].is_moving()) g.q[static_cast<Eigen::Index>(j)] = 0.01 * (j + 1);
  Contact c;
  c.link = static_cast<int>(hand.links.size()) - 1;
  c.p_O = {0.01, 0.02, 0.03};
  c.n_O = Eigen::Vector3d(1, 1, 0).normalized();
  g.contacts = {c};
  g.force_closure = true;
  g.epsilon = 0.0123;
  g.alpha_rad = 0.2;
  g.alpha_approach_rad = 0.3;
  g.chi_m2 = 1.5e-4;
  g.region_rank = 4;
  g.times.finger_s = 0.004;
  doc.grasps = {g};
  return doc;
}

TEST(PlanJson, RoundTripsEveryField) {
  const HandModel hand = load_hand("parallel_gripper");
  const PlanDocument doc = sample_plan(hand);
  const std::string path = temp_path("roundtrip.json");
  write_plan_file(path, doc, hand);
  const nlohmann::json j = read_plan_json(path);
  EXPECT_EQ(plan_hand_path(j), "/abs/hand.yaml");
  EXPECT_EQ(plan_object_path(j), "/abs/box.obj");
  const PlanDocument back = plan_from_json(j, hand);
  EXPECT_EQ(back.hand_name, hand.name);
  EXPECT_EQ(back.planner, PlannerKind::kCord);
  EXPECT_EQ(back.params.seed, 7u);
  EXPECT_EQ(plan_contact_model(back).mu, 0.7);
  EXPECT_EQ(plan_contact_model(back).soft_finger_radius_m, 0.004);
  EXPECT_EQ(back.palm_width_m, 0.085);
  EXPECT_EQ(back.object_scale, 2.5);
  ASSERT_TRUE(back.cord.has_value());
  EXPECT_EQ(back.cord->xi_min_m, 0.02);
  EXPECT_EQ(back.cord->eps_len_m, 2e-9);
  EXPECT_EQ(back.cord->xor_backend, XorBackend::kClipper);
  EXPECT_EQ(back.cord->sphere_sequence, SphereSequence::kFibonacci);
  EXPECT_EQ(back.cord->side_cord_policy, SideCordPolicy::kShrink);
  EXPECT_EQ(back.stats.attempts, 3);
  ASSERT_TRUE(back.stats.first_force_closure_s.has_value());
  ASSERT_EQ(back.grasps.size(), 1u);
  const Grasp& a = doc.grasps[0];
  const Grasp& b = back.grasps[0];
  EXPECT_TRUE(b.X_OB.isApprox(a.X_OB, 1e-12));
  EXPECT_TRUE(b.X_OG.isApprox(a.X_OG, 1e-12));
  EXPECT_TRUE(b.q.isApprox(a.q, 1e-15));
  ASSERT_EQ(b.contacts.size(), 1u);
  EXPECT_EQ(b.contacts[0].link, a.contacts[0].link);
  EXPECT_TRUE(b.contacts[0].p_O.isApprox(a.contacts[0].p_O, 1e-15));
  EXPECT_TRUE(b.contacts[0].n_O.isApprox(a.contacts[0].n_O, 1e-15));
  EXPECT_EQ(b.epsilon, a.epsilon);
  EXPECT_EQ(b.alpha_rad, a.alpha_rad);
  EXPECT_EQ(b.alpha_approach_rad, a.alpha_approach_rad);
  EXPECT_EQ(b.chi_m2, a.chi_m2);
  EXPECT_EQ(b.region_rank, a.region_rank);
  EXPECT_EQ(b.times.finger_s, a.times.finger_s);
  std::filesystem::remove(path);
}

TEST(PlanJson, MarksAnInterruptedPlanIncompleteAndReadsOldFilesAsComplete) {
  const HandModel hand = load_hand("parallel_gripper");
  PlanDocument doc = sample_plan(hand);
  nlohmann::json j = plan_to_json(doc, hand);
  EXPECT_EQ(j.at("complete"), true);
  EXPECT_FALSE(j.contains("interrupted"));
  EXPECT_EQ(plan_from_json(j, hand).interrupted, "");
  j.erase("complete");  // written before the key existed
  EXPECT_EQ(plan_from_json(j, hand).interrupted, "");

  doc.interrupted = "SIGINT";
  j = plan_to_json(doc, hand);
  EXPECT_EQ(j.at("complete"), false);
  EXPECT_EQ(j.at("interrupted"), "SIGINT");
  const PlanDocument back = plan_from_json(j, hand);
  EXPECT_EQ(back.interrupted, "SIGINT");
  EXPECT_TRUE(back.stats.interrupted);
  EXPECT_EQ(back.grasps.size(), doc.grasps.size());
  j["complete"] = "no";
  EXPECT_THROW(plan_from_json(j, hand, "plan.json"), InputError);
}

TEST(PlanJson, RefusesAPlanMadeForAnotherHand) {
  const HandModel gripper = load_hand("parallel_gripper");
  const HandModel sah = load_hand("cordgrasp_sah");
  const nlohmann::json j = plan_to_json(sample_plan(gripper), gripper);
  try {
    plan_from_json(j, sah);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("parallel_gripper"), std::string::npos) << e.what();
  }
}

TEST(PlanJson, ReadNamesTheFileWhenMissingOrNotAPlan) {
  EXPECT_THROW(read_plan_json(temp_path("missing.json")), InputError);
  const std::string path = temp_path("not_a_plan.json");
  std::ofstream(path) << "{\"format\": \"something-else\"}";
  try {
    read_plan_json(path);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}

std::string decode_error(const nlohmann::json& j, const HandModel& hand) {
  try {
    plan_from_json(j, hand, "/abs/plan.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(PlanJson, AMissingParameterIsAnErrorNamingFileAndKey) {
  const HandModel hand = load_hand("parallel_gripper");
  const nlohmann::json full = plan_to_json(sample_plan(hand), hand);
  nlohmann::json j = full;
  j["parameters"].erase("seed");
  EXPECT_EQ(decode_error(j, hand), "/abs/plan.json: parameters.seed: missing");
  j = full;
  j["parameters"]["quality"]["contact"].erase("mu");  // no silent default μ
  EXPECT_EQ(decode_error(j, hand), "/abs/plan.json: parameters.quality.contact.mu: missing");
  j = full;
  j["parameters"]["cord"].erase("xi_min_m");
  EXPECT_EQ(decode_error(j, hand), "/abs/plan.json: parameters.cord.xi_min_m: missing");
  j = full;
  j.erase("parameters");
  EXPECT_EQ(decode_error(j, hand), "/abs/plan.json: parameters: missing");
}

TEST(PlanJson, AnUnknownPlannerOrEnumNameIsAnError) {
  const HandModel hand = load_hand("parallel_gripper");
  nlohmann::json j = plan_to_json(sample_plan(hand), hand);
  j["parameters"]["cord"]["side_cord_policy"] = "sometimes";
  EXPECT_NE(decode_error(j, hand).find("allowed: discard, shrink, empty"), std::string::npos)
      << decode_error(j, hand);
  j = plan_to_json(sample_plan(hand), hand);
  j["parameters"]["planner"] = "magic";
  EXPECT_NE(decode_error(j, hand).find("allowed: cord, generic"), std::string::npos);
}

TEST(PlanJson, AGenericPlanHasNoCordParameters) {
  const HandModel hand = load_hand("parallel_gripper");
  PlanDocument doc = sample_plan(hand);
  doc.planner = PlannerKind::kGeneric;
  doc.cord.reset();
  const nlohmann::json j = plan_to_json(doc, hand);
  EXPECT_TRUE(j.at("parameters").at("cord").is_null());
  EXPECT_FALSE(plan_from_json(j, hand).cord.has_value());
}

TEST(PlanJson, RefusesFormatVersion1WithAMessage) {
  const HandModel hand = load_hand("parallel_gripper");
  nlohmann::json j = plan_to_json(sample_plan(hand), hand);
  j["format_version"] = 1;
  const std::string path = temp_path("v1.json");
  std::ofstream(path) << j.dump();
  try {
    read_plan_json(path);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("format_version 1"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}

TEST(PlanJson, Version2PlansAreUpgradedInOneStep) {
  // A format-2 plan as early version-2 writers left it: candidate filters in its parameters
  // and stats, no object scale, preshape joints, approach α or measures.
  const HandModel hand = load_hand("parallel_gripper");
  const PlanDocument doc = sample_plan(hand);
  const nlohmann::json current = plan_to_json(doc, hand);
  EXPECT_EQ(current["format_version"], 3);
  EXPECT_FALSE(current["parameters"].contains("candidate"));
  nlohmann::json old = current;
  old["format_version"] = 2;
  old["parameters"]["candidate"] = {{"min_epsilon", 0.01}, {"min_fingers", 3},
                                    {"max_com_offset", 0.0}, {"max_push_imbalance", 0.0},
                                    {"approach_extra_m", 0.0}};
  old["stats"]["filtered"] = 2;
  old["inputs"]["object"].erase("scale");
  for (auto* key : {"preshape_joints", "alpha_approach_rad", "measures"})
    old["grasps"][0].erase(key);
  const std::string path = temp_path("v2.json");
  std::ofstream(path) << old.dump();
  const nlohmann::json upgraded = read_plan_json(path);
  EXPECT_EQ(upgraded["format_version"], 3);
  EXPECT_FALSE(upgraded["parameters"].contains("candidate"));
  EXPECT_FALSE(upgraded["stats"].contains("filtered"));
  const PlanDocument back = plan_from_json(upgraded, hand, path);
  EXPECT_EQ(back.object_scale, 1.0);
  EXPECT_EQ(back.grasps[0].alpha_approach_rad, doc.grasps[0].alpha_rad);
  EXPECT_EQ(back.grasps[0].q, doc.grasps[0].q);
  // The current reader patches nothing: a format-3 plan without those keys is an error.
  nlohmann::json bare = current;
  bare["grasps"][0].erase("measures");
  EXPECT_THROW(plan_from_json(bare, hand, "bare.json"), InputError);
  std::filesystem::remove(path);
}

TEST(PlanJson, PlansWrittenBeforeTheFallbackReadAsPlannedWithoutIt) {
  const HandModel hand = load_hand("parallel_gripper");
  const PlanDocument doc = sample_plan(hand);
  nlohmann::json current = plan_to_json(doc, hand);
  EXPECT_EQ(current["parameters"]["fallback_attempts"], PlanParams{}.fallback_attempts);
  current["parameters"].erase("fallback_attempts");
  const std::string path = temp_path("before_fallback.json");
  std::ofstream(path) << current.dump();
  const PlanDocument back = plan_from_json(read_plan_json(path), hand, path);
  EXPECT_EQ(back.params.fallback_attempts, 0);
  std::filesystem::remove(path);
}

TEST(PlanJson, StatsRoundTripAndOlderFilesReadMissingCountsAsZero) {
  const HandModel hand = load_hand("parallel_gripper");
  PlanDocument doc = sample_plan(hand);
  doc.stats.inside_object = 5;
  doc.stats.sampled_attempts = 2;
  doc.stats.timed_out = true;
  nlohmann::json j = plan_to_json(doc, hand);
  EXPECT_EQ(j["stats"]["machine_dependent"], true);
  EXPECT_FALSE(j["stats"].contains("interrupted"));  // the document's own key
  const PlanStats back = plan_from_json(j, hand).stats;
  EXPECT_EQ(back.inside_object, 5);
  EXPECT_EQ(back.sampled_attempts, 2);
  EXPECT_TRUE(back.timed_out);
  EXPECT_EQ(back.first_force_closure_s, doc.stats.first_force_closure_s);

  j["stats"].erase("inside_object");  // written before the check existed
  j["stats"].erase("sampled_attempts");
  const PlanStats old = plan_from_json(j, hand).stats;
  EXPECT_EQ(old.inside_object, 0);
  EXPECT_EQ(old.sampled_attempts, 0);
  EXPECT_EQ(old.attempts, doc.stats.attempts);

  j["stats"]["attempts"] = "three";
  try {
    plan_from_json(j, hand, "typo.json");
    FAIL() << "a count of the wrong type was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("typo.json: stats.attempts"), std::string::npos)
        << e.what();
  }
}

TEST(PlanJson, PosesReadBackBitForBit) {
  const HandModel hand = load_hand("parallel_gripper");
  PlanDocument doc = sample_plan(hand);
  for (int k = 1; k < 20; ++k) {  // rotations whose quaternion round trip is inexact
    Grasp g = doc.grasps[0];
    g.X_OB = Eigen::Translation3d(0.01 * k, 0.02, -0.03) *
             Eigen::AngleAxisd(0.31 * k, Eigen::Vector3d(k, 1.0 - k, 0.5).normalized());
    doc.grasps.push_back(g);
  }
  const std::string path = temp_path("exact_pose.json");
  write_plan_file(path, doc, hand);
  const PlanDocument back = plan_from_json(read_plan_json(path), hand);
  ASSERT_EQ(back.grasps.size(), doc.grasps.size());
  for (size_t k = 0; k < doc.grasps.size(); ++k) {
    EXPECT_TRUE(back.grasps[k].X_OB.matrix() == doc.grasps[k].X_OB.matrix()) << "grasp " << k;
    EXPECT_TRUE(back.grasps[k].X_OG.matrix() == doc.grasps[k].X_OG.matrix()) << "grasp " << k;
  }
  std::filesystem::remove(path);
}

// A plan edited by hand or by another tool: each bad value is refused with its JSON path.
void expect_refused(const std::string& name, const std::function<void(nlohmann::json&)>& edit,
                    const std::string& expected) {
  const HandModel hand = load_hand("parallel_gripper");
  nlohmann::json j = plan_to_json(sample_plan(hand), hand);
  edit(j);
  try {
    plan_from_json(j, hand, "edited.json");
    ADD_FAILURE() << name << ": accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << name << ": "
                                                                       << e.what();
  }
}

TEST(PlanJson, RefusesNonUnitQuaternionsFarPositionsNaNAndJointsOutsideLimits) {
  expect_refused("zero quaternion", [](nlohmann::json& j) {
    j["grasps"][0]["hand_pose"]["quaternion_wxyz"] = {0, 0, 0, 0};
    j["grasps"][0]["hand_pose"].erase("rotation_rowmajor");
  }, "grasps[0].hand_pose.quaternion_wxyz: not a unit quaternion");
  expect_refused("far hand", [](nlohmann::json& j) {
    j["grasps"][0]["hand_pose"]["position_m"] = {1e300, 0, 0};
  }, "grasps[0].hand_pose.position_m");
  expect_refused("null coordinate", [](nlohmann::json& j) {
    j["grasps"][0]["gcp_pose"]["position_m"][1] = nullptr;
  }, "grasps[0].gcp_pose.position_m[1]: not a number");
  expect_refused("matrix off the quaternion", [](nlohmann::json& j) {
    j["grasps"][0]["hand_pose"]["rotation_rowmajor"][0] = 0.5;
  }, "rotation_rowmajor: does not match");
  const HandModel hand = load_hand("parallel_gripper");
  std::string moving;
  for (const Joint& joint : hand.joints)
    if (joint.is_moving()) moving = joint.name;
  ASSERT_FALSE(moving.empty());
  expect_refused("joint past its limit", [&](nlohmann::json& j) {
    j["grasps"][0]["joints"][moving] = 1e3;
  }, "outside the joint's limits");
}

TEST(PlanJson, AMissingOrBadObjectScaleIsRefused) {
  // (Version-2 plans without one read as scale 1: Version2PlansAreUpgradedInOneStep.)
  const HandModel hand = load_hand("parallel_gripper");
  nlohmann::json j = plan_to_json(sample_plan(hand), hand);
  j["inputs"]["object"].erase("scale");
  EXPECT_THROW(plan_from_json(j, hand), InputError);
  j["inputs"]["object"]["scale"] = -2.0;
  try {
    plan_from_json(j, hand, "/abs/plan.json");
    FAIL() << "a negative scale was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/abs/plan.json: inputs.object.scale"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace cordgrasp
