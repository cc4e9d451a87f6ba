// hand_fingers: chains moved by each actor, thumb flag and fingertip.
#include "cordgrasp/core/hand_fingers.h"

#include <gtest/gtest.h>

#include "cordgrasp/core/geometry_points.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/kinematics.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

TEST(HandFingers, MimicDrivenFingerIsItsOwnFingerOfTheSameActor) {
  const HandModel h = load_hand("parallel_gripper");
  const std::vector<Finger> f = hand_fingers(h);
  ASSERT_EQ(f.size(), 2u);
  EXPECT_EQ(f[0].actor, 0);
  EXPECT_EQ(f[1].actor, 0);
  EXPECT_EQ(h.links[f[0].links.front()].name, "left_finger");
  EXPECT_EQ(h.links[f[1].links.front()].name, "right_finger");
  EXPECT_TRUE(f[0].is_thumb);
  EXPECT_FALSE(f[1].is_thumb);
}

TEST(HandFingers, SahModelHasOneChainPerActorWithTipsAtTheFingerEnds) {
  const HandModel h = load_hand("cordgrasp_sah");
  const std::vector<Finger> f = hand_fingers(h);
  ASSERT_EQ(f.size(), 4u);
  const auto X = link_poses(h, apply_couplings(h, h.preshape));
  for (size_t i = 0; i < f.size(); ++i) {
    EXPECT_EQ(f[i].actor, static_cast<int>(i));
    EXPECT_EQ(f[i].links.size(), 3u);  // proximal, middle, distal (the knuckle is not moved)
    EXPECT_EQ(f[i].tip_link, f[i].links.back());
    EXPECT_EQ(f[i].is_thumb, h.actors[i].name == "thumb");
    // The tip is the finger point farthest from the proximal joint: no collision point of the
    // finger is farther.
    const Eigen::Vector3d p_root = X[f[i].links.front()].translation();
    const double d_tip = (X[f[i].tip_link] * f[i].p_tip_L - p_root).norm();
    for (int l : f[i].links) {
      std::vector<Eigen::Vector3d> pts;
      append_collision_points(h.links[l], pts);
      for (const auto& p : pts) EXPECT_LE((X[l] * p - p_root).norm(), d_tip + 1e-12);
    }
  }
}

TEST(GeometryPoints, BoundTheGeometry) {
  Geometry box;
  box.kind = Geometry::Kind::kBox;
  box.box_size_m = Eigen::Vector3d(0.1, 0.2, 0.3);
  box.X_LG.translation() = Eigen::Vector3d(1, 0, 0);
  const auto pb = geometry_points(box);
  ASSERT_EQ(pb.size(), 8u);
  Eigen::Vector3d lo = pb[0], hi = pb[0];
  for (const auto& p : pb) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  EXPECT_TRUE(lo.isApprox(Eigen::Vector3d(0.95, -0.1, -0.15)));
  EXPECT_TRUE(hi.isApprox(Eigen::Vector3d(1.05, 0.1, 0.15)));
  Geometry sphere;
  sphere.kind = Geometry::Kind::kSphere;
  sphere.radius_m = 0.02;
  for (const auto& p : geometry_points(sphere)) EXPECT_NEAR(p.norm(), 0.02, 1e-15);
}

}  // namespace
}  // namespace cordgrasp
