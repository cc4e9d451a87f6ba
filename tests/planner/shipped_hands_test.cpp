// Finger stage with the hands shipped in assets/hands.
#include <gtest/gtest.h>

#include "cordgrasp/collision/bullet_hand_collider.h"
#include "cordgrasp/core/finger_stage.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/kinematics.h"
#include "cordgrasp/core/shapes.h"

namespace cordgrasp {
namespace {

constexpr double kContactTol_m = 0.5e-3;  // spec: contacts within 0.5 mm of the surface
constexpr double kPosTol_m = 1e-6;

TEST(ShippedParallelGripper, ClosesUntilThePadsTouchTheBoxFaces) {
  const HandModel hand = load_hand("parallel_gripper");
  const double half = 0.02;
  const Mesh box = make_box_mesh(Eigen::Vector3d::Constant(2.0 * half));
  auto collider = make_bullet_hand_collider(hand, box);
  const HandSetup setup = prepare_hand(hand, *collider);
  // GCP at the box centre: its x axis points at the left (thumb) pad.
  const FingerResult r =
      run_finger_stage(hand, setup, *collider, Eigen::Isometry3d::Identity(), 0.0);
  ASSERT_EQ(r.status, FingerStatus::kOk) << to_string(r.status);
  EXPECT_EQ(r.retreat_steps, 0);
  ASSERT_EQ(r.contacts.size(), 2u);
  collider->set_link_poses(link_poses(hand, r.q, r.X_OB));
  double sides = 0.0;
  for (const Contact& c : r.contacts) {
    EXPECT_NEAR(std::abs(c.p_O.x()), half, kPosTol_m);  // on a ±x face
    EXPECT_GT(std::abs(c.n_O.x()), 1.0 - 1e-6);
    sides += c.p_O.x();
    const auto prox = collider->link_object_proximity(c.link, 1.0);
    ASSERT_TRUE(prox.has_value());
    EXPECT_GE(prox->distance_m, 0.0);
    EXPECT_LE(prox->distance_m, kContactTol_m);
  }
  EXPECT_NEAR(sides, 0.0, kPosTol_m);  // one pad on each face
}

TEST(ShippedParallelGripper, ThumbCalibrationPointsFromTheLeftPadToTheRightOne) {
  const HandModel hand = load_hand("parallel_gripper");
  const Eigen::Matrix3d R = thumb_calibration(hand, hand.preshape);
  // The description puts GCP +x towards the left (thumb) finger: o_h = −x.
  EXPECT_TRUE(R.col(0).isApprox(-Eigen::Vector3d::UnitX(), 1e-9)) << R;
  EXPECT_TRUE(R.col(2).isApprox(Eigen::Vector3d::UnitZ(), 1e-12));
}

TEST(ShippedDefaultHand, WrapsALongCylinderWithAtLeastThreeContacts) {
  const HandModel hand = load_hand(default_hand_name());
  const Mesh cylinder = make_cylinder_mesh(0.0175, 0.25);
  auto collider = make_bullet_hand_collider(hand, cylinder);
  const HandSetup setup = prepare_hand(hand, *collider);
  // Approach along −x onto the side of the cylinder, thumb towards −y.
  GraspRegion region;
  region.p1 = {0.15, 0.0, 0.0};
  region.p_l = {0.002, -0.0175, 0.0};
  region.p_r = {0.002, 0.0175, 0.0};
  region.p_m = {0.002, 0.0, 0.0};
  region.normal = Eigen::Vector3d::UnitZ();
  const Eigen::Isometry3d X_OG = gcp_pose_for_region(region, setup.R_GH);
  const FingerResult r = run_finger_stage(hand, setup, *collider, X_OG, 0.15 - 0.0175);
  ASSERT_EQ(r.status, FingerStatus::kOk) << to_string(r.status);
  EXPECT_GE(r.contacts.size(), 3u);
  for (const Contact& c : r.contacts) EXPECT_NEAR(c.p_O.head<2>().norm(), 0.0175, 1e-3);
}

}  // namespace
}  // namespace cordgrasp
