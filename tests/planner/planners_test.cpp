// Cord planner on hand-made regions and the generic baseline, with primitive hands.
#include <gtest/gtest.h>

#include "cordgrasp/collision/bullet_hand_collider.h"
#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/core/plan_cord_grasps.h"
#include "cordgrasp/core/plan_generic_grasps.h"
#include "cordgrasp/core/shapes.h"
#include "plan_internal.h"
#include "test_hands.h"

namespace cordgrasp {
namespace {

// Region seen from P1 = (d, 0, 0) in the cross-section z = 0 of a cylinder of radius r along z:
// P_l, P_r are the silhouette (tangent) points, as Case I would find them.
GraspRegion cylinder_region(double r, double d, double chi) {
  GraspRegion g;
  g.p1 = {d, 0.0, 0.0};
  const double x = r * r / d, y = r * std::sqrt(1.0 - r * r / (d * d));
  g.p_l = {x, y, 0.0};
  g.p_r = {x, -y, 0.0};
  g.p_m = 0.5 * (g.p_l + g.p_r);
  g.normal = Eigen::Vector3d::UnitZ();
  g.chi_m2 = chi;
  return g;
}

TEST(PlanCordGrasps, FindsForceClosureOnHandMadeCylinderRegions) {
  const Mesh cylinder = make_cylinder_mesh(0.015, 0.3);
  const HandModel hand = test::make_three_finger_hand();
  auto collider = make_bullet_hand_collider(hand, cylinder);
  // The better region (lower χ) is given second: ranks follow χ, not input order.
  const std::vector<GraspRegion> regions = {cylinder_region(0.015, 0.2, 2e-4),
                                            cylinder_region(0.015, 0.15, 1e-4)};
  PlanParams params;
  params.grasps = 2;
  const PlanResult plan =
      plan_cord_grasps_from_regions(cylinder, hand, *collider, regions, params, 0.25);
  ASSERT_EQ(plan.grasps.size(), 2u);
  EXPECT_EQ(plan.stats.regions, 2);
  EXPECT_EQ(plan.stats.regions_processed, 2);
  // Both regions lie in one cross-section: the second's first grasp is a near copy of the
  // first region's (skipped: DiversityParams), its 180°-rolled retry is not.
  EXPECT_EQ(plan.stats.similar, 1);
  EXPECT_EQ(plan.stats.force_closure, 2 + plan.stats.similar);
  ASSERT_TRUE(plan.stats.first_force_closure_s.has_value());
  EXPECT_GE(*plan.stats.first_force_closure_s, 0.25);
  const Grasp& g = plan.grasps[0];
  EXPECT_TRUE(g.force_closure);
  EXPECT_GT(g.epsilon, 0.0);
  EXPECT_EQ(g.region_rank, 0);
  EXPECT_EQ(g.chi_m2, 1e-4);
  EXPECT_EQ(plan.grasps[1].region_rank, 1);
  EXPECT_EQ(g.times.exploration_s, 0.25);
  EXPECT_GE(g.contacts.size(), 3u);
  // Approach along −x, perpendicular to the cylinder axis z: α = 0.
  EXPECT_NEAR(g.alpha_approach_rad, 0.0, 1e-9);
  EXPECT_TRUE(g.X_OG.linear().col(2).isApprox(-Eigen::Vector3d::UnitX(), 1e-12));
  EXPECT_EQ(g.q.size(), static_cast<Eigen::Index>(hand.joints.size()));
}

TEST(PlanCordGrasps, StopsAtTheRequestedNumberOfGrasps) {
  const Mesh cylinder = make_cylinder_mesh(0.015, 0.3);
  const HandModel hand = test::make_three_finger_hand();
  auto collider = make_bullet_hand_collider(hand, cylinder);
  const std::vector<GraspRegion> regions(5, cylinder_region(0.015, 0.2, 1e-4));
  const PlanResult plan = plan_cord_grasps_from_regions(cylinder, hand, *collider, regions, {});
  EXPECT_EQ(plan.grasps.size(), 1u);
  EXPECT_EQ(plan.stats.regions_processed, 1);
}

TEST(PlanCordGrasps, CountsBadCasesAndKeepsGoing) {
  // A region approaching along the cylinder's axis from its centre: the palm straddles the
  // surface and 20 retreat steps cannot free it; the next region works.
  const Mesh cylinder = make_cylinder_mesh(0.015, 0.3);
  const HandModel hand = test::make_three_finger_hand();
  auto collider = make_bullet_hand_collider(hand, cylinder);
  GraspRegion inside = cylinder_region(0.015, 0.2, 1e-5);
  inside.p1 = {0.0, 0.0, 0.0};
  inside.p_l = {0.01, 0.0, 0.1};
  inside.p_r = {-0.01, 0.0, 0.1};
  inside.p_m = {0.0, 0.0, 0.1};
  PlanParams params;
  params.finger.max_retreat_steps = 20;
  const PlanResult plan = plan_cord_grasps_from_regions(
      cylinder, hand, *collider, {inside, cylinder_region(0.015, 0.2, 1e-4)}, params);
  ASSERT_EQ(plan.grasps.size(), 1u);
  EXPECT_EQ(plan.grasps[0].region_rank, 1);
  EXPECT_EQ(plan.stats.attempts, 3);  // region 0 as is and rolled, then region 1
  EXPECT_EQ(plan.stats.attempts, plan.stats.force_closure + plan.stats.no_contact +
                                     plan.stats.one_contact + plan.stats.cannot_retreat +
                                     plan.stats.not_force_closure + plan.stats.inside_object);
}

TEST(PlanCordGrasps, ContactsTouchedFromInsideAClosedObjectAreNoGrasp) {
  // The hand placed inside a closed box crosses no surface: it approaches the wall from within
  // and closes its fingers on it. Those contacts are rejected (inside_object); the same box
  // without its far face is open, has no inside, and the same attempts are judged as usual.
  const Mesh closed = make_box_mesh(Eigen::Vector3d::Constant(0.4));
  Mesh open = closed;
  open.triangles.clear();
  for (const Eigen::Vector3i& t : closed.triangles) {
    bool far_face = true;
    for (int k = 0; k < 3; ++k) far_face = far_face && closed.vertices[t[k]].x() < -0.19;
    if (!far_face) open.triangles.push_back(t);
  }
  ASSERT_EQ(open.triangles.size(), closed.triangles.size() - 2);
  GraspRegion within;
  within.p1 = {0.0, 0.0, 0.0};
  within.p_l = {0.1, 0.03, 0.0};
  within.p_r = {0.1, -0.03, 0.0};
  within.p_m = {0.1, 0.0, 0.0};
  within.normal = Eigen::Vector3d::UnitZ();
  within.chi_m2 = 1e-4;
  const HandModel hand = test::make_three_finger_hand();
  PlanParams params;
  params.fallback_attempts = 0;
  auto in_closed = make_bullet_hand_collider(hand, closed);
  const PlanResult a = plan_cord_grasps_from_regions(closed, hand, *in_closed, {within}, params);
  EXPECT_TRUE(a.grasps.empty());
  EXPECT_GT(a.stats.inside_object, 0);
  EXPECT_EQ(a.stats.attempts, a.stats.inside_object + a.stats.no_contact + a.stats.one_contact);
  auto in_open = make_bullet_hand_collider(hand, open);
  const PlanResult b = plan_cord_grasps_from_regions(open, hand, *in_open, {within}, params);
  EXPECT_EQ(b.stats.inside_object, 0);
  EXPECT_EQ(b.stats.attempts, a.stats.attempts);
  EXPECT_EQ(b.stats.force_closure + b.stats.not_force_closure, a.stats.inside_object);
}

TEST(PlanCordGrasps, NoRegionsGiveNoGraspAndNoCrash) {
  const Mesh box = make_box_mesh(Eigen::Vector3d::Constant(0.05));
  const HandModel hand = test::make_three_finger_hand();
  auto collider = make_bullet_hand_collider(hand, box);
  const PlanResult plan = plan_cord_grasps_from_regions(box, hand, *collider, {}, {});
  EXPECT_TRUE(plan.grasps.empty());
  EXPECT_FALSE(plan.stats.first_force_closure_s.has_value());
}

TEST(PlanCordGrasps, SpentRegionsGoOnAtSampledPointsApproachedToTheFarSide) {
  const Mesh box = make_box_mesh({0.04, 0.05, 0.06});
  const HandModel hand = test::make_three_finger_hand();
  auto collider = make_bullet_hand_collider(hand, box);
  PlanParams params;
  params.grasps = 2;
  params.seed = 3;
  params.time_limit_s = 30.0;
  params.max_attempts = 0;  // the regions' attempts spent at once
  const PlanResult plan = plan_cord_grasps(box, hand, *collider, CordParams{}, params);
  PlanParams fallback = params;
  fallback.max_attempts = params.fallback_attempts;
  const PlanResult sampled = plan_cord_fallback_grasps(box, hand, *collider, fallback);
  ASSERT_EQ(plan.grasps.size(), 2u);
  ASSERT_EQ(sampled.grasps.size(), 2u);
  EXPECT_EQ(plan.stats.regions_processed, 0);
  EXPECT_EQ(plan.stats.sampled_attempts, plan.stats.attempts);
  EXPECT_EQ(plan.stats.attempts, sampled.stats.attempts);
  EXPECT_FALSE(plan.stats.attempt_budget_reached);
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_FALSE(plan.grasps[i].region_rank.has_value());
    EXPECT_FALSE(plan.grasps[i].region.has_value());
    EXPECT_TRUE(plan.grasps[i].X_OG.isApprox(sampled.grasps[i].X_OG, 0.0));
  }

  params.fallback_attempts = 0;  // the paper's planner
  const PlanResult paper = plan_cord_grasps(box, hand, *collider, CordParams{}, params);
  EXPECT_TRUE(paper.grasps.empty());
  EXPECT_EQ(paper.stats.attempts, 0);
  EXPECT_EQ(paper.stats.sampled_attempts, 0);
  EXPECT_TRUE(paper.stats.attempt_budget_reached);
}

TEST(PlanCordGrasps, TheFallbackClosesAcrossASphereWhereTheGenericPlannerTouchesItsNearSide) {
  // A hand whose GCP lies where its fingertips meet, as `hand init` drafts it. At the same
  // sampled points (same seed) the generic baseline starts the GCP on the surface and only
  // retreats: the fingertips close on the sphere's near cap. The fallback moves the hand in
  // along the normal until the GCP reaches the sphere's middle: the fingers close across it.
  constexpr double kRadiusM = 0.02;
  constexpr double kFingertipsMeetM = 0.09;  // above the palm, fingers 0.092 m long
  const Mesh sphere = make_sphere_mesh(kRadiusM);
  HandModel hand = test::make_three_finger_hand();
  hand.gcp.X_LG.translation() = Eigen::Vector3d(0, 0, kFingertipsMeetM);
  auto collider = make_bullet_hand_collider(hand, sphere);
  PlanParams params;
  params.grasps = 1000;  // count every force-closure grasp of the attempts
  params.max_attempts = 60;
  params.seed = 5;
  params.time_limit_s = 60.0;
  const PlanResult generic = plan_generic_grasps(sphere, hand, *collider, params);
  const PlanResult fallback = plan_cord_fallback_grasps(sphere, hand, *collider, params);
  ASSERT_EQ(generic.stats.attempts, 60);
  ASSERT_EQ(fallback.stats.attempts, 60);
  EXPECT_GT(fallback.stats.force_closure, generic.stats.force_closure + 30);
  // GCP depth below the surface (the sphere is centred at the origin). The face normal through
  // a point away from its face's centre passes the centre by up to half a face (1.3 mm here).
  auto depth_m = [&](const Grasp& g) { return kRadiusM - g.X_OG.translation().norm(); };
  constexpr double kPlacementToleranceM = 2e-3;
  for (const Grasp& g : generic.grasps) EXPECT_LT(depth_m(g), kPlacementToleranceM);
  ASSERT_FALSE(fallback.grasps.empty());
  for (const Grasp& g : fallback.grasps) EXPECT_NEAR(depth_m(g), kRadiusM, kPlacementToleranceM);
}

TEST(Thickness, IsTheDistanceToTheFarSideAlongTheInwardNormalAndZeroOnAnOpenSide) {
  const Mesh box = make_box_mesh({0.04, 0.05, 0.06});
  const Eigen::Vector3d p(0.02, 0.01, -0.01), z = -Eigen::Vector3d::UnitX();
  EXPECT_NEAR(internal::thickness_m(box, nullptr, p, z, 1.0), 0.04, 1e-12);
  const Eigen::Vector3d top(0.0, 0.0, 0.03);
  EXPECT_NEAR(internal::thickness_m(box, nullptr, top, -Eigen::Vector3d::UnitZ(), 1.0), 0.06,
              1e-12);
  EXPECT_EQ(internal::thickness_m(box, nullptr, p, z, 0.03), 0.0);  // beyond the reach
  Mesh open = box;  // without the far (−x) face the ray leaves the soup
  open.triangles.clear();
  for (const Eigen::Vector3i& t : box.triangles) {
    bool far_face = true;
    for (int k = 0; k < 3; ++k) far_face = far_face && box.vertices[t[k]].x() < -0.019;
    if (!far_face) open.triangles.push_back(t);
  }
  EXPECT_EQ(internal::thickness_m(open, nullptr, p, z, 1.0), 0.0);
}

TEST(PlanCordGrasps, RegionsThatGiveTheGraspsSampleNothing) {
  const Mesh cylinder = make_cylinder_mesh(0.015, 0.3);
  const HandModel hand = test::make_three_finger_hand();
  auto collider = make_bullet_hand_collider(hand, cylinder);
  PlanParams params;
  params.time_limit_s = 30.0;
  const PlanResult plan = plan_cord_grasps(cylinder, hand, *collider, CordParams{}, params);
  ASSERT_EQ(plan.grasps.size(), 1u);
  EXPECT_TRUE(plan.grasps[0].region_rank.has_value());
  EXPECT_EQ(plan.stats.sampled_attempts, 0);
}

TEST(OutwardFaceNormal, FlipsInwardWoundTrianglesByRayParity) {
  Mesh box = make_box_mesh(Eigen::Vector3d::Constant(0.05));
  for (size_t i = 0; i < box.triangles.size(); i += 2)
    std::swap(box.triangles[i][1], box.triangles[i][2]);  // half the faces wound inwards
  for (size_t i = 0; i < box.triangles.size(); ++i) {
    const Eigen::Vector3i& t = box.triangles[i];
    const Eigen::Vector3d p = (box.vertices[t[0]] + box.vertices[t[1]] + box.vertices[t[2]]) / 3.0;
    const Eigen::Vector3d n = outward_face_normal(box, static_cast<int>(i), p);
    EXPECT_GT(n.dot(p), 0.0) << "face " << i;  // box centred at the origin
  }
}

TEST(OutwardFaceNormal, HandlesConcaveFacesInsideATorusHole) {
  const Mesh torus = make_torus_mesh(0.05, 0.015);
  int inner = 0;
  for (size_t i = 0; i < torus.triangles.size(); ++i) {
    const Eigen::Vector3i& t = torus.triangles[i];
    const Eigen::Vector3d p =
        (torus.vertices[t[0]] + torus.vertices[t[1]] + torus.vertices[t[2]]) / 3.0;
    const Eigen::Vector2d radial = p.head<2>().normalized();
    const Eigen::Vector3d tube_center(0.05 * radial.x(), 0.05 * radial.y(), 0.0);
    const Eigen::Vector3d n = outward_face_normal(torus, static_cast<int>(i), p);
    EXPECT_GT(n.dot(p - tube_center), 0.0) << "face " << i;
    if ((p - tube_center).head<2>().dot(radial) < -0.01) ++inner;  // faces toward the hole
  }
  EXPECT_GT(inner, 0);  // the vertex-mean rule would get every one of these wrong
}

TEST(OutwardFaceNormal, TheObjectsBvhGivesTheSameNormals) {
  // A torus with the inner half of its faces wound inwards: parity decides every one of them.
  Mesh torus = make_torus_mesh(0.05, 0.015);
  for (size_t i = 0; i < torus.triangles.size(); i += 2)
    std::swap(torus.triangles[i][1], torus.triangles[i][2]);
  const MeshBvh bvh = build_object_bvh(torus);
  const Eigen::Vector3d c = vertex_mean(torus);
  const double r = bounding_radius(torus, c);
  for (size_t i = 0; i < torus.triangles.size(); ++i) {
    const Eigen::Vector3i& t = torus.triangles[i];
    const Eigen::Vector3d p =
        (torus.vertices[t[0]] + 2.0 * torus.vertices[t[1]] + torus.vertices[t[2]]) / 4.0;
    const int k = static_cast<int>(i);
    EXPECT_TRUE(outward_face_normal(torus, k, p, c, r, &bvh) == outward_face_normal(torus, k, p))
        << "face " << i;
  }
}

TEST(PlanGenericGrasps, FindsForceClosureGraspsOnABox) {
  const Mesh box = make_box_mesh({0.04, 0.05, 0.06});
  const HandModel hand = test::make_three_finger_hand();
  auto collider = make_bullet_hand_collider(hand, box);
  PlanParams params;
  params.grasps = 3;
  params.seed = 3;
  params.time_limit_s = 30.0;
  const PlanResult plan = plan_generic_grasps(box, hand, *collider, params);
  ASSERT_EQ(plan.grasps.size(), 3u);
  for (const Grasp& g : plan.grasps) {
    EXPECT_TRUE(g.force_closure);
    EXPECT_GT(g.epsilon, 0.0);
    EXPECT_FALSE(g.region_rank.has_value());
    EXPECT_GE(g.alpha_rad, 0.0);
    EXPECT_LE(g.alpha_rad, M_PI / 4.0 + 1e-12);
  }
  EXPECT_GE(plan.stats.attempts, 3);
  EXPECT_EQ(plan.stats.attempts, plan.stats.force_closure + plan.stats.no_contact +
                                     plan.stats.one_contact + plan.stats.cannot_retreat +
                                     plan.stats.not_force_closure + plan.stats.inside_object);
}

TEST(PlanGenericGrasps, SameSeedSameGraspsDifferentSeedDifferentGrasps) {
  const Mesh box = make_box_mesh({0.04, 0.05, 0.06});
  const HandModel hand = test::make_three_finger_hand();
  auto collider = make_bullet_hand_collider(hand, box);
  PlanParams params;
  params.grasps = 2;
  params.time_limit_s = 30.0;
  const PlanResult a = plan_generic_grasps(box, hand, *collider, params);
  const PlanResult b = plan_generic_grasps(box, hand, *collider, params);
  params.seed = 99;
  const PlanResult c = plan_generic_grasps(box, hand, *collider, params);
  ASSERT_EQ(a.grasps.size(), 2u);
  ASSERT_EQ(b.grasps.size(), 2u);
  ASSERT_FALSE(c.grasps.empty());
  EXPECT_EQ(a.stats.attempts, b.stats.attempts);
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_TRUE(a.grasps[i].X_OG.isApprox(b.grasps[i].X_OG, 0.0));
    EXPECT_EQ(a.grasps[i].q, b.grasps[i].q);
    EXPECT_EQ(a.grasps[i].epsilon, b.grasps[i].epsilon);
  }
  EXPECT_FALSE(a.grasps[0].X_OG.isApprox(c.grasps[0].X_OG, 1e-9));
}

TEST(PlanGenericGrasps, StopsAtMaxAttemptsWhenNothingCanHold) {
  // The gripper is far too small for a 1 m cube: never force closure.
  const Mesh big = make_box_mesh(Eigen::Vector3d::Constant(1.0));
  const HandModel hand = test::make_parallel_gripper();
  auto collider = make_bullet_hand_collider(hand, big);
  PlanParams params;
  params.max_attempts = 20;
  const PlanResult plan = plan_generic_grasps(big, hand, *collider, params);
  EXPECT_TRUE(plan.grasps.empty());
  EXPECT_EQ(plan.stats.attempts, 20);
  EXPECT_FALSE(plan.stats.timed_out);
}

TEST(CordPlanner, PlannedGraspsCarryTheirCandidateMeasures) {
  const Mesh cylinder = make_cylinder_mesh(0.015, 0.3);
  const HandModel hand = test::make_three_finger_hand();
  auto collider = make_bullet_hand_collider(hand, cylinder);
  const std::vector<GraspRegion> regions = {cylinder_region(0.015, 0.15, 1e-4)};
  const PlanResult plan =
      plan_cord_grasps_from_regions(cylinder, hand, *collider, regions, PlanParams{});
  ASSERT_EQ(plan.grasps.size(), 1u);
  const Grasp& g = plan.grasps[0];
  EXPECT_GE(g.measures.fingers_in_contact, 2);
  EXPECT_LT(g.measures.com_offset, 0.1);  // on the cylinder's middle cross-section
}

}  // namespace
}  // namespace cordgrasp
