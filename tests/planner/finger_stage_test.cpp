// Finger stage (docs/algorithm.md §7) with hands built from primitives and the Bullet collider.
#include "cordgrasp/core/finger_stage.h"

#include <gtest/gtest.h>

#include "cordgrasp/collision/bullet_hand_collider.h"
#include "cordgrasp/core/grasp_quality.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/kinematics.h"
#include "cordgrasp/core/mesh_bvh.h"
#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/core/plan_cord_grasps.h"
#include "cordgrasp/core/shapes.h"
#include "test_hands.h"

namespace cordgrasp {
namespace {

constexpr double kContactTol_m = 0.5e-3;  // spec: contacts within 0.5 mm of the surface
constexpr double kPosTol_m = 1e-6;

Eigen::Isometry3d at(const Eigen::Vector3d& p,
                     const Eigen::Matrix3d& R = Eigen::Matrix3d::Identity()) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = R;
  X.translation() = p;
  return X;
}

// GCP +z pointing down (−z of the object frame).
Eigen::Matrix3d pointing_down() {
  return Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()).toRotationMatrix();
}

struct Scene {
  HandModel hand;
  Mesh object;
  std::unique_ptr<HandObjectCollider> collider;
  HandSetup setup;
  Scene(HandModel h, Mesh m) : hand(std::move(h)), object(std::move(m)) {
    collider = make_bullet_hand_collider(hand, object);
    setup = prepare_hand(hand, *collider);
  }
  FingerResult run(const Eigen::Isometry3d& X_OG, double travel = 0.0,
                   const FingerParams& params = {}) {
    return run_finger_stage(hand, setup, *collider, X_OG, travel, params);
  }
};

TEST(PrepareHand, SplitsActorAndStaticLinksAndCalibratesThumb) {
  Scene s(test::make_parallel_gripper(), make_box_mesh(Eigen::Vector3d::Constant(0.05)));
  ASSERT_EQ(s.setup.actor_links.size(), 2u);
  EXPECT_EQ(s.setup.actor_links[0], std::vector<int>{1});
  EXPECT_EQ(s.setup.actor_links[1], std::vector<int>{2});
  EXPECT_EQ(s.setup.static_links, std::vector<int>{0});
  // Thumb = left finger at −x: o_h points from it to the right finger, +x of the GCP.
  EXPECT_TRUE(s.setup.R_GH.isApprox(Eigen::Matrix3d::Identity(), 1e-12));
  // Palm–finger pairs are kinematic neighbours (one prismatic joint): ignored.
  EXPECT_TRUE(s.setup.ignore_pair[0 * 3 + 1]);
  EXPECT_FALSE(s.setup.ignore_pair[1 * 3 + 2]);
}

TEST(PrepareHand, MimicJointsFollowTheirActor) {
  Scene s(test::make_three_finger_hand(true), make_sphere_mesh(0.03));
  ASSERT_EQ(s.setup.actor_joints.size(), 3u);
  EXPECT_EQ(s.setup.actor_joints[0], (std::vector<int>{0, 1}));
  EXPECT_EQ(s.setup.actor_links[0], (std::vector<int>{1, 2}));
}

TEST(FingerStage, ParallelGripperStopsAtTheBoxFaces) {
  Scene s(test::make_parallel_gripper(), make_box_mesh(Eigen::Vector3d::Constant(0.05)));
  const FingerResult r = s.run(at(Eigen::Vector3d::Zero()));
  ASSERT_EQ(r.status, FingerStatus::kOk) << to_string(r.status);
  EXPECT_EQ(r.retreat_steps, 0);
  ASSERT_EQ(r.contacts.size(), 2u);
  // Open inner faces at ∓0.055, box faces at ∓0.025: each finger travels 0.03 minus the gap.
  for (int j = 0; j < 2; ++j) {
    EXPECT_LE(r.q[j], 0.03 + kPosTol_m);
    EXPECT_GE(r.q[j], 0.03 - kContactTol_m);
  }
  for (const Contact& c : r.contacts) {
    EXPECT_NEAR(std::abs(c.p_O.x()), 0.025, kPosTol_m);
    const double side = c.link == 1 ? -1.0 : 1.0;  // left finger touches the −x face
    EXPECT_NEAR(c.p_O.x(), side * 0.025, kPosTol_m);
    EXPECT_GT(c.n_O.x() * side, 1.0 - 1e-6);
    s.collider->set_link_poses(link_poses(s.hand, r.q, r.X_OB));
    const auto prox = s.collider->link_object_proximity(c.link, 1.0);
    ASSERT_TRUE(prox.has_value());
    EXPECT_GE(prox->distance_m, 0.0);
    EXPECT_LE(prox->distance_m, kContactTol_m);
  }
}

TEST(FingerStage, ContactToleranceIsHonouredWhenTightened) {
  Scene s(test::make_parallel_gripper(), make_box_mesh(Eigen::Vector3d::Constant(0.05)));
  FingerParams p;
  p.contact_tolerance_m = 0.02e-3;
  const FingerResult r = s.run(at(Eigen::Vector3d::Zero()), 0.0, p);
  ASSERT_EQ(r.status, FingerStatus::kOk);
  for (int j = 0; j < 2; ++j) EXPECT_NEAR(r.q[j], 0.03, 0.02e-3 + kPosTol_m);
}

TEST(FingerStage, ThreeFingerHandWrapsASphereWithCouplingsHonoured) {
  Scene s(test::make_three_finger_hand(true), make_sphere_mesh(0.03));
  const FingerResult r = s.run(at(Eigen::Vector3d::Zero()));
  ASSERT_EQ(r.status, FingerStatus::kOk) << to_string(r.status);
  EXPECT_GE(r.contacts.size(), 3u);
  for (int f = 0; f < 3; ++f) EXPECT_EQ(r.q[2 * f + 1], r.q[2 * f]);  // distal mimics proximal
  for (const Contact& c : r.contacts) {
    EXPECT_NEAR(c.p_O.norm(), 0.03, 1e-3);  // on the (faceted) sphere
    EXPECT_GT(c.n_O.dot(c.p_O.normalized()), 0.9);
  }
  const WrenchSpaceObject w = prepare_wrench_space(s.object, {});
  EXPECT_TRUE(evaluate_grasp_quality(r.contacts, w, {}).force_closure);
}

TEST(FingerStage, FingersStopOnEachOtherWithoutAnObjectBetweenThem) {
  // Object far away and travel beyond the middle allowed: the fingers meet and stop there.
  HandModel gripper = test::make_parallel_gripper();
  for (auto& j : gripper.joints) j.upper = 0.08;
  Scene s(gripper, make_box_mesh(Eigen::Vector3d::Constant(0.05)));
  const FingerResult r = s.run(at({0.5, 0.0, 0.0}));
  EXPECT_EQ(r.status, FingerStatus::kNoContact);
  EXPECT_TRUE(r.contacts.empty());
  // Inner faces (0.11 apart when open) meet when q_left + q_right = 0.11.
  EXPECT_NEAR(r.q[0] + r.q[1], 0.11, 1e-4);
  EXPECT_LE(r.q[0] + r.q[1], 0.11 + kPosTol_m);
}

TEST(FingerStage, ReportsOneContactWhenOnlyOneFingerReaches) {
  Mesh box = make_box_mesh(Eigen::Vector3d::Constant(0.02));
  for (auto& v : box.vertices) v.x() -= 0.035;  // spans x ∈ [−0.045, −0.025]
  Scene s(test::make_parallel_gripper(), box);
  const FingerResult r = s.run(at(Eigen::Vector3d::Zero()));
  EXPECT_EQ(r.status, FingerStatus::kOneContact);
  EXPECT_EQ(r.contacts.size(), 1u);
}

// The shipped gripper has one actor (right pad mimics the left): off-centre, the first pad to
// touch stops both. Centring shifts the hand by half the other pad's gap and closes again.
TEST(FingerStage, OneActorGripperOffCentreIsCentredOnTheObject) {
  constexpr double kOffset_m = 0.01, kHalf_m = 0.015;
  Mesh box = make_box_mesh(Eigen::Vector3d::Constant(2 * kHalf_m));
  for (auto& v : box.vertices) v.x() += kOffset_m;  // faces at x = −0.005 and x = 0.025
  Scene s(load_hand("parallel_gripper"), box);
  ASSERT_EQ(s.setup.actor_links.size(), 1u);
  FingerParams no_centring;
  no_centring.centre_single_actor = false;
  EXPECT_EQ(s.run(at(Eigen::Vector3d::Zero()), 0.0, no_centring).status,
            FingerStatus::kOneContact);
  const FingerResult r = s.run(at(Eigen::Vector3d::Zero()));
  ASSERT_EQ(r.status, FingerStatus::kOk) << to_string(r.status);
  ASSERT_EQ(r.contacts.size(), 2u);
  EXPECT_NEAR(r.X_OG.translation().x(), kOffset_m, kContactTol_m);
  EXPECT_NEAR(r.X_OG.translation().y(), 0.0, kPosTol_m);
  EXPECT_NEAR(r.X_OG.translation().z(), 0.0, kPosTol_m);
  for (const Contact& c : r.contacts) EXPECT_NEAR(std::abs(c.p_O.x() - kOffset_m), kHalf_m, 1e-4);
}

TEST(FingerStage, ReportsCannotRetreatWhenTheHandStartsInside) {
  // A 3 m long bar: the palm straddles its side faces and retreating along it never frees it.
  Scene s(test::make_parallel_gripper(), make_box_mesh({0.05, 0.05, 3.0}));
  const FingerResult r = s.run(at(Eigen::Vector3d::Zero()));
  EXPECT_EQ(r.status, FingerStatus::kCannotRetreat);
  EXPECT_EQ(r.retreat_steps, FingerParams{}.max_retreat_steps);
}

TEST(FingerStage, ApproachStopsWhenTheGcpReachesTheSurface) {
  Scene s(test::make_parallel_gripper(), make_box_mesh(Eigen::Vector3d::Constant(0.05)));
  const FingerResult r = s.run(at({0, 0, 0.2}, pointing_down()), 0.175);
  ASSERT_EQ(r.status, FingerStatus::kOk);
  EXPECT_EQ(r.approach_steps, 175);
  EXPECT_EQ(r.retreat_steps, 0);
  EXPECT_NEAR(r.X_OG.translation().z(), 0.025, kPosTol_m);
}

TEST(FingerStage, ApproachStopsAtFirstCollisionAndRetreats) {
  // A wide slab: the finger tips (2 cm beyond the GCP) hit its top face first.
  Scene s(test::make_parallel_gripper(), make_box_mesh({0.3, 0.3, 0.05}));
  const FingerResult r = s.run(at({0, 0, 0.2}, pointing_down()), 0.175);
  EXPECT_GE(r.retreat_steps, 1);
  const double tip_z = r.X_OG.translation().z() - 0.02;
  EXPECT_GE(tip_z, 0.025);
  EXPECT_LE(tip_z, 0.025 + FingerParams{}.approach_step_m + kPosTol_m);
}

TEST(GcpPoseForRegion, PutsGcpAtP1ApproachingPmWithThumbTowardsPl) {
  const HandModel hand = test::make_parallel_gripper();
  GraspRegion region;
  region.p1 = {0.0, 0.0, 0.2};
  region.p_l = {-0.02, 0.01, 0.0};
  region.p_r = {0.02, -0.01, 0.0};
  region.p_m = 0.5 * (region.p_l + region.p_r);
  region.normal = Eigen::Vector3d::UnitY();
  const Eigen::Matrix3d R_GH = thumb_calibration(hand, hand.preshape);
  for (bool flip : {false, true}) {
    const Eigen::Isometry3d X_OG = gcp_pose_for_region(region, R_GH, flip);
    EXPECT_TRUE(X_OG.translation().isApprox(region.p1, 1e-12));
    EXPECT_TRUE(X_OG.linear().col(2).isApprox(-Eigen::Vector3d::UnitZ(), 1e-12));
    EXPECT_TRUE(X_OG.linear().isUnitary(1e-12));
    EXPECT_GT(X_OG.linear().determinant(), 0.0);
    // The thumb (left finger) ends up on the P_l side, or on the P_r side when flipped.
    const Eigen::Isometry3d X_OB = root_pose_for_gcp(hand, hand.preshape, X_OG);
    const Eigen::Vector3d thumb = link_poses(hand, hand.preshape, X_OB)[1].translation();
    const bool near_l = (thumb - region.p_l).norm() < (thumb - region.p_r).norm();
    EXPECT_EQ(near_l, !flip);
  }
}

TEST(ApproachTravel, IsTheDistanceToTheFirstSurfaceHit) {
  const Mesh box = make_box_mesh(Eigen::Vector3d::Constant(0.05));
  GraspRegion region;
  region.p1 = {0.0, 0.0, 0.2};
  region.p_m = {0.0, 0.0, 0.0};
  EXPECT_NEAR(approach_travel_m(box, region), 0.175, 1e-12);
  region.p1 = {0.2, 0.2, 0.2};  // ray passes beside the box: ‖P_m − P1‖
  region.p_m = {0.2, 0.2, 0.0};
  EXPECT_NEAR(approach_travel_m(box, region), 0.2, 1e-12);
}

TEST(ApproachTravel, TheObjectsBvhGivesTheSameTravel) {
  const Mesh torus = make_torus_mesh(0.05, 0.015);
  const MeshBvh bvh = build_object_bvh(torus);
  const Eigen::Vector3d c = vertex_mean(torus);
  const double r = bounding_radius(torus, c);
  int hits = 0;
  for (int k = 0; k < 200; ++k) {  // approaches from a ring of points towards the torus
    const double a = 0.0314 * k;
    GraspRegion region;
    region.p1 = {0.12 * std::cos(a), 0.12 * std::sin(a), 0.05 * std::sin(3.0 * a)};
    region.p_m = {0.03 * std::cos(2.0 * a), 0.03 * std::sin(a), 0.0};
    const double brute = approach_travel_m(torus, region);
    EXPECT_EQ(approach_travel_m(torus, region, c, r, &bvh), brute) << "approach " << k;
    hits += brute < (region.p_m - region.p1).norm() ? 1 : 0;
  }
  EXPECT_GT(hits, 100);  // most approaches meet the torus before P_m
}

}  // namespace
}  // namespace cordgrasp
