// Front cords (docs/algorithm.md §3): Case I on a box, Case II on a book-like box, eligibility,
// and the hull-chain construction equals TIGHTEN.
#include "cordgrasp/core/front_cord.h"

#include <gtest/gtest.h>

#include <random>

#include "cord_test_util.h"
#include "cordgrasp/core/explore_cords.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/seed_cord_eligible.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

constexpr double kTol_m = 1e-12;

TEST(FrontCord, CaseIOnABoxIsTheFaceTowardsP1) {
  // 4 cm cube; guide triangle in the plane z = 5 mm, P1 on the −x side, P2P3 beyond the cube.
  const CordObject box = make_cord_object(make_box_mesh(Eigen::Vector3d(0.04, 0.04, 0.04)));
  const double z = 0.005;
  const Eigen::Vector3d p1(-0.15, 0.0, z), p2(0.05, 0.08, z), p3(0.05, -0.08, z);
  for (CordConstruction how : {CordConstruction::kHullChain, CordConstruction::kTighten}) {
    CordParams params;
    params.cord_construction = how;
    FrontCordFailure why;
    const std::optional<FrontCord> fc = front_cord(box, p1, p2, p3, params, &why);
    ASSERT_TRUE(fc.has_value()) << int(why);
    EXPECT_EQ(fc->cord_case, CordCase::kI);
    const Polyline3 cord = fc->cord_3d();
    // P_l is the corner seen from P1 on the P2 (+y) side, P_r the one on the P3 side.
    EXPECT_LT((cord.back() - Eigen::Vector3d(-0.02, 0.02, z)).norm(), kTol_m);
    EXPECT_LT((cord.front() - Eigen::Vector3d(-0.02, -0.02, z)).norm(), kTol_m);
    // The front cord is the straight face x = −0.02 between them.
    for (const Eigen::Vector3d& p : cord) EXPECT_NEAR(p.x(), -0.02, kTol_m);
    EXPECT_NEAR(cord_xi(fc->cord), 0.02, kTol_m);
    EXPECT_TRUE(seed_cord_eligible(*fc, params));
  }
}

TEST(FrontCord, CaseIIOnABookLikeBoxWrapsTheNearEdge) {
  // 20 × 15 × 3 cm book; in the plane y = 1 mm its section is x ∈ ±0.1, z ∈ ±0.015.
  const CordObject book = make_cord_object(make_box_mesh(Eigen::Vector3d(0.2, 0.15, 0.03)));
  const double y = 0.001;
  const Eigen::Vector3d p1(-0.25, y, 0.0), p2(-0.06, y, 0.05), p3(-0.06, y, -0.05);
  ASSERT_TRUE(is_acute_triangle(p1, p2, p3));
  const std::optional<FrontCord> fc = front_cord(book, p1, p2, p3);
  ASSERT_TRUE(fc.has_value());
  EXPECT_EQ(fc->cord_case, CordCase::kII);
  const Polyline3 cord = fc->cord_3d();
  // P_l, P_r: where P2P3 enters and leaves the book; the cord wraps the spine x = −0.1.
  const Polyline3 expected = {
      {-0.06, y, -0.015}, {-0.1, y, -0.015}, {-0.1, y, 0.015}, {-0.06, y, 0.015}};
  EXPECT_LT(test::polyline_distance(cord, expected), kTol_m);
  EXPECT_LT((cord.back() - expected.back()).norm(), kTol_m);    // P_l (P2 side)
  EXPECT_LT((cord.front() - expected.front()).norm(), kTol_m);  // P_r (P3 side)
  EXPECT_NEAR(cord_xi(fc->cord), std::hypot(0.04, 0.015), kTol_m);
  // Parallel end segments pass the squeeze test: the seed is eligible.
  EXPECT_TRUE(seed_cord_eligible(*fc));
}

TEST(SeedCordEligible, SqueezeTestRejectsConvergingEndsAbove45Degrees) {
  constexpr double kQuarterPi = 0.78539816339744831;
  // Cords run P_r → … → P_l. Parallel ends (a box spine): pass.
  EXPECT_TRUE(passes_squeeze_test({{0, 0}, {-1, 0}, {-1, 1}, {0, 1}}, kQuarterPi));
  // Ends meeting at a right-angled corner: the rays intersect at 90° > 45°: fail.
  EXPECT_FALSE(passes_squeeze_test({{1, 0}, {0, 0}, {0, 1}}, kQuarterPi));
  // A shallow cap: ends converge at a small angle: pass.
  EXPECT_TRUE(passes_squeeze_test({{0, 0}, {-1, 0.2}, {-1, 0.8}, {0, 1}}, kQuarterPi));
  // Diverging ends never squeeze the object out.
  EXPECT_TRUE(passes_squeeze_test({{0, 0}, {-1, -1}, {-1, 2}, {0, 1}}, kQuarterPi));
}

/// Counts front cords built and eligible over `tries` Algorithm-1 style guide triangles.
std::pair<int, int> count_eligible(const Mesh& mesh, int tries) {
  const CordObject object = make_cord_object(mesh);
  std::mt19937_64 rng(17);
  int built = 0, eligible = 0;
  for (int k = 0; k < tries; ++k) {
    const test::GuideTriangle t = test::random_guide_triangle(object, rng);
    const std::optional<FrontCord> fc = front_cord(object, t.p1, t.p2, t.p3);
    if (!fc) continue;
    ++built;
    eligible += seed_cord_eligible(*fc) ? 1 : 0;
  }
  return {built, eligible};
}

TEST(SeedCordEligible, RejectsAnObjectTooSmallForTheHand) {
  // An 8 mm cube: every cord point is within its 13.9 mm diameter of P_m, so ξ < 15 mm.
  const Mesh small = make_box_mesh(Eigen::Vector3d(0.008, 0.008, 0.008));
  const auto [built, eligible] = count_eligible(small, 3000);
  EXPECT_GT(built, 100);
  EXPECT_EQ(eligible, 0);
  CordParams params;
  params.max_iterations = 1;
  EXPECT_TRUE(explore_cords(small, 0.085, params).empty());
}

TEST(SeedCordEligible, RejectsCordsTooWideForTheHand) {
  // Not a random-sampling claim: on any large object, small Case II caps or sharp oblique
  // corners remain eligible. Here the seeds span the object: ξ > ξ_max.
  // Case I around a 20 cm cube: the front face from corner to corner, ξ = 10 cm.
  const CordObject cube = make_cord_object(make_box_mesh(Eigen::Vector3d(0.2, 0.2, 0.2)));
  const double z = 0.01;
  const auto face = front_cord(cube, Eigen::Vector3d(-0.5, 0.0, z), Eigen::Vector3d(0.2, 0.3, z),
                               Eigen::Vector3d(0.2, -0.3, z));
  ASSERT_TRUE(face.has_value());
  EXPECT_EQ(face->cord_case, CordCase::kI);
  EXPECT_NEAR(cord_xi(face->cord), 0.1, kTol_m);
  EXPECT_FALSE(seed_cord_eligible(*face));
  // Case II through a 16 cm thick slab: the cord wraps the whole spine, ξ > 8 cm.
  const CordObject slab = make_cord_object(make_box_mesh(Eigen::Vector3d(0.4, 0.3, 0.16)));
  const auto spine = front_cord(slab, Eigen::Vector3d(-0.6, 0.0, 0.0),
                                Eigen::Vector3d(-0.1, 0.0, 0.2), Eigen::Vector3d(-0.1, 0.0, -0.2));
  ASSERT_TRUE(spine.has_value());
  EXPECT_EQ(spine->cord_case, CordCase::kII);
  EXPECT_GT(cord_xi(spine->cord), 0.08);
  EXPECT_FALSE(seed_cord_eligible(*spine));
}

/// The default hull-chain construction gives the same front cord as TIGHTEN run on both
/// Case I steps, on `tries` random guide triangles; returns how many cords were compared.
int expect_hull_chain_matches_tighten(const Mesh& mesh, int tries, std::mt19937_64& rng) {
  SCOPED_TRACE(mesh.name);
  const CordObject object = make_cord_object(mesh);
  CordParams hull, tighten;
  hull.cord_construction = CordConstruction::kHullChain;
  tighten.cord_construction = CordConstruction::kTighten;
  int compared = 0;
  for (int k = 0; k < tries; ++k) {
    const test::GuideTriangle t = test::random_guide_triangle(object, rng);
    FrontCordFailure why_hull, why_tighten;
    const auto a = front_cord(object, t.p1, t.p2, t.p3, hull, &why_hull);
    const auto b = front_cord(object, t.p1, t.p2, t.p3, tighten, &why_tighten);
    EXPECT_EQ(a.has_value(), b.has_value());
    EXPECT_EQ(int(why_hull), int(why_tighten));
    if (!a || !b) continue;
    EXPECT_EQ(a->cord_case, b->cord_case);
    EXPECT_LT((a->p_l() - b->p_l()).norm(), kTol_m);
    EXPECT_LT((a->p_r() - b->p_r()).norm(), kTol_m);
    EXPECT_LT(test::polyline_distance(a->cord, b->cord), 1e-11);
    ++compared;
  }
  return compared;
}

TEST(FrontCord, HullChainConstructionEqualsTighten) {
  std::mt19937_64 rng(31);
  int compared = 0;
  for (const Mesh& mesh : test::test_shapes())
    compared += expect_hull_chain_matches_tighten(mesh, 400, rng);
  EXPECT_GE(compared, 300);
}

TEST(FrontCordDataset, HullChainConstructionEqualsTighten) {
  CORDGRASP_REQUIRE_SHARED_DATA();
  std::mt19937_64 rng(37);
  int compared = 0;
  for (const std::string dir : {"kit", "ycb", "simox"})
    for (const std::string& path :
         test::files_in(test::shared_data_dir() + "/objects/" + dir, ".obj"))
      compared += expect_hull_chain_matches_tighten(load_mesh(path), 100, rng);
  EXPECT_GE(compared, 1000);
}

}  // namespace
}  // namespace cordgrasp
