// Bullet HandObjectCollider (cordgrasp::collision) against analytic distances on primitives.
#include <gtest/gtest.h>

#include <random>

#include "cordgrasp/collision/bullet_hand_collider.h"
#include "cordgrasp/core/explore_cords.h"
#include "cordgrasp/core/kinematics.h"
#include "cordgrasp/core/shapes.h"
#include "test_hands.h"

namespace cordgrasp {
namespace {

constexpr double kDistTol_m = 1e-5;  // GJK/EPA accuracy at hand scale
constexpr double kHalf_m = 0.025;    // object: 5 cm cube at the origin

HandModel one_link_hand(const Geometry& g) {
  HandModel h;
  h.name = "one_link";
  test::add_link(h, "body", g);
  h.gcp.link = 0;
  h.preshape = Eigen::VectorXd::Zero(0);
  return h;
}

Geometry sphere_geometry(double r) {
  Geometry g;
  g.kind = Geometry::Kind::kSphere;
  g.radius_m = r;
  return g;
}

Eigen::Isometry3d at(const Eigen::Vector3d& p) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() = p;
  return X;
}

double box_distance(const Eigen::Vector3d& p) {
  const Eigen::Vector3d outside = (p.cwiseAbs().array() - kHalf_m).max(0.0).matrix();
  return outside.norm();
}

TEST(BulletCollider, SphereLinkDistanceMatchesAnalyticBoxDistance) {
  const double r = 0.01;
  auto collider = make_bullet_hand_collider(one_link_hand(sphere_geometry(r)),
                                            make_box_mesh(Eigen::Vector3d::Constant(0.05)));
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-0.06, 0.06);
  int checked = 0;
  for (int i = 0; i < 400; ++i) {
    const Eigen::Vector3d c(u(rng), u(rng), u(rng));
    const double expected = box_distance(c) - r;
    if (box_distance(c) <= 0.0 || expected > 0.02) continue;  // centre inside or too far
    collider->set_link_pose(0, at(c));
    const auto prox = collider->link_object_proximity(0, 0.02);
    ASSERT_TRUE(prox.has_value()) << c.transpose();
    if (expected > 0.0) {
      EXPECT_NEAR(prox->distance_m, expected, kDistTol_m) << c.transpose();
      EXPECT_FALSE(collider->link_collides_with_object(0));
      // Witness on the box surface; normal from it towards the sphere centre.
      EXPECT_NEAR(box_distance(prox->p_object_O), 0.0, kDistTol_m);
      const Eigen::Vector3d to_centre = (c - prox->p_object_O).normalized();
      EXPECT_GT(prox->n_O.dot(to_centre), 1.0 - 1e-6);
      EXPECT_NEAR((prox->p_link_O - c).norm(), r, kDistTol_m);
    } else {
      EXPECT_TRUE(collider->link_collides_with_object(0)) << c.transpose();
      EXPECT_LT(prox->distance_m, 0.0);
    }
    ++checked;
  }
  EXPECT_GT(checked, 50);
}

TEST(BulletCollider, SphereOverlappingAFaceReportsPenetrationDepth) {
  const double r = 0.01;
  auto collider = make_bullet_hand_collider(one_link_hand(sphere_geometry(r)),
                                            make_box_mesh(Eigen::Vector3d::Constant(0.05)));
  collider->set_link_pose(0, at({kHalf_m + r - 0.002, 0.003, -0.004}));
  const auto prox = collider->link_object_proximity(0, 0.0);
  ASSERT_TRUE(prox.has_value());
  EXPECT_NEAR(prox->distance_m, -0.002, kDistTol_m);
  EXPECT_GT(prox->n_O.x(), 1.0 - 1e-6);
}

TEST(BulletCollider, ReportsNothingBeyondMaxDistance) {
  auto collider = make_bullet_hand_collider(one_link_hand(sphere_geometry(0.01)),
                                            make_box_mesh(Eigen::Vector3d::Constant(0.05)));
  collider->set_link_pose(0, at({0.05, 0, 0}));  // 15 mm gap
  EXPECT_FALSE(collider->link_object_proximity(0, 0.014).has_value());
  EXPECT_TRUE(collider->link_object_proximity(0, 0.016).has_value());
}

TEST(BulletCollider, BoxCylinderAndHullLinksMatchFaceGaps) {
  const double gap = 0.004;
  Geometry box = test::box_geometry({0.02, 0.03, 0.01}, Eigen::Vector3d::Zero());
  Geometry cyl;
  cyl.kind = Geometry::Kind::kCylinder;
  cyl.radius_m = 0.008;
  cyl.length_m = 0.03;
  Geometry hull;
  hull.kind = Geometry::Kind::kMesh;
  hull.mesh = std::make_shared<Mesh>(make_box_mesh({0.02, 0.03, 0.01}));
  struct Case {
    Geometry g;
    double half_x;  // extent of the link towards the object face
  };
  for (const Case& c : {Case{box, 0.01}, Case{cyl, 0.008}, Case{hull, 0.01}}) {
    auto collider = make_bullet_hand_collider(one_link_hand(c.g),
                                              make_box_mesh(Eigen::Vector3d::Constant(0.05)));
    collider->set_link_pose(0, at({kHalf_m + c.half_x + gap, 0.001, 0.002}));
    const auto prox = collider->link_object_proximity(0, 0.01);
    ASSERT_TRUE(prox.has_value());
    EXPECT_NEAR(prox->distance_m, gap, kDistTol_m);
    EXPECT_NEAR(prox->p_object_O.x(), kHalf_m, kDistTol_m);
    EXPECT_FALSE(collider->link_collides_with_object(0));
    collider->set_link_pose(0, at({kHalf_m + c.half_x - 0.001, 0.001, 0.002}));
    EXPECT_TRUE(collider->link_collides_with_object(0));
  }
}

TEST(BulletCollider, LinkLinkCollisionFollowsSphereRadii) {
  HandModel h = one_link_hand(sphere_geometry(0.01));
  test::add_link(h, "other", sphere_geometry(0.015));
  auto collider = make_bullet_hand_collider(h, make_box_mesh(Eigen::Vector3d::Constant(0.05)));
  collider->set_link_pose(0, at({0.2, 0, 0}));
  collider->set_link_pose(1, at({0.2, 0.0249, 0}));
  EXPECT_TRUE(collider->links_collide(0, 1));
  collider->set_link_pose(1, at({0.2, 0.0251, 0}));
  EXPECT_FALSE(collider->links_collide(0, 1));
}

TEST(BulletCollider, LinkEntirelyInsideAClosedObjectIsNotReported) {
  // Surface-based queries, as documented: nothing crosses the surface here.
  auto collider = make_bullet_hand_collider(one_link_hand(sphere_geometry(0.005)),
                                            make_box_mesh(Eigen::Vector3d::Constant(0.05)));
  collider->set_link_pose(0, at(Eigen::Vector3d::Zero()));
  EXPECT_FALSE(collider->link_collides_with_object(0));
}

TEST(BulletCollider, LinksWithoutGeometryNeverCollide) {
  HandModel h = one_link_hand(sphere_geometry(0.01));
  h.links[0].collisions.clear();
  auto collider = make_bullet_hand_collider(h, make_box_mesh(Eigen::Vector3d::Constant(0.05)));
  EXPECT_FALSE(collider->has_geometry(0));
  collider->set_link_pose(0, at({kHalf_m, 0, 0}));
  EXPECT_FALSE(collider->link_collides_with_object(0));
  EXPECT_FALSE(collider->link_object_proximity(0, 1.0).has_value());
}

TEST(BulletCollider, ThrowsOnMeshWithoutUsableTriangles) {
  Mesh flat;
  flat.name = "flat";
  flat.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  flat.triangles = {{0, 1, 2}};
  EXPECT_THROW(make_bullet_hand_collider(one_link_hand(sphere_geometry(0.01)), flat),
               std::invalid_argument);
}

}  // namespace
}  // namespace cordgrasp

namespace cordgrasp {
namespace {

// The collider answers repeated queries from clearance certificates while links move less than
// the certified clearance; along random small-step walks it must agree with a fresh collider.
TEST(BulletCollider, CertifiedAnswersMatchFreshQueriesAlongRandomWalks) {
  const HandModel hand = test::make_three_finger_hand(false);
  const Mesh sphere = make_sphere_mesh(0.03);
  auto cached = make_bullet_hand_collider(hand, sphere);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> step(-0.03, 0.03);
  Eigen::VectorXd q = Eigen::VectorXd::Constant(static_cast<Eigen::Index>(hand.joints.size()), 0.4);
  Eigen::Isometry3d X_OB = Eigen::Isometry3d::Identity();
  X_OB.translation() = Eigen::Vector3d(0.0, 0.0, -0.06);
  int collisions = 0, checks = 0;
  for (int i = 0; i < 300; ++i) {
    // Joints kept off 0, where the proximal phalanges touch the palm exactly (a verdict left
    // to rounding).
    for (Eigen::Index j = 0; j < q.size(); ++j) q[j] = std::clamp(q[j] + step(rng), 0.05, 1.6);
    X_OB.translation().z() += 0.2 * step(rng);
    const auto X = link_poses(hand, q, X_OB);
    cached->set_link_poses(X);
    auto fresh = make_bullet_hand_collider(hand, sphere);
    fresh->set_link_poses(X);
    for (int l = 0; l < static_cast<int>(hand.links.size()); ++l) {
      const bool c = fresh->link_collides_with_object(l);
      EXPECT_EQ(cached->link_collides_with_object(l), c) << "step " << i << " link " << l;
      collisions += c;
      ++checks;
      for (int m = l + 1; m < static_cast<int>(hand.links.size()); ++m)
        EXPECT_EQ(cached->links_collide(l, m), fresh->links_collide(l, m))
            << "step " << i << " links " << l << ", " << m;
    }
  }
  EXPECT_GT(collisions, 0);
  EXPECT_LT(collisions, checks);
}

TEST(BulletCollider, DistanceLowerBoundNeverExceedsTheDistance) {
  const HandModel hand = test::make_three_finger_hand(false);
  const Mesh box = make_box_mesh({0.04, 0.06, 0.05});
  auto collider = make_bullet_hand_collider(hand, box);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-0.15, 0.15);
  for (int i = 0; i < 100; ++i) {
    Eigen::Isometry3d X_OB = Eigen::Isometry3d::Identity();
    X_OB.linear() = Eigen::Quaterniond::UnitRandom().toRotationMatrix();
    X_OB.translation() = Eigen::Vector3d(u(rng), u(rng), u(rng));
    collider->set_link_poses(link_poses(hand, hand.preshape, X_OB));
    for (int l = 0; l < static_cast<int>(hand.links.size()); ++l) {
      const double bound = collider->link_object_distance_lower_bound(l);
      const auto prox = collider->link_object_proximity(l, 1.0);
      ASSERT_TRUE(prox.has_value());
      EXPECT_LE(bound, prox->distance_m + 1e-9);
    }
  }
}

TEST(BulletCollider, SharesItsObjectBvhWithTheCordExploration) {
  // The collider keeps the object's BVH (build_object_bvh) and the exploration run on it
  // finds the regions it finds with a BVH of its own: one copy of a large scan, same plans.
  const Mesh box = make_box_mesh(Eigen::Vector3d(0.06, 0.04, 0.03));
  auto collider = make_bullet_hand_collider(one_link_hand(sphere_geometry(0.01)), box);
  const std::shared_ptr<const MeshBvh> bvh = collider->object_bvh();
  ASSERT_TRUE(bvh);
  EXPECT_EQ(bvh->triangles.size(), box.triangles.size());
  EXPECT_EQ(bvh.get(), collider->object_bvh().get());  // kept, not rebuilt per call
  CordParams params;
  params.sets = 4;
  const auto own = explore_cords(box, 0.08, params);
  const auto shared = explore_cords(box, 0.08, params, nullptr, bvh);
  ASSERT_FALSE(own.empty());
  ASSERT_EQ(own.size(), shared.size());
  for (size_t k = 0; k < own.size(); ++k) EXPECT_EQ(own[k].chi_m2, shared[k].chi_m2) << k;
}

}  // namespace
}  // namespace cordgrasp
