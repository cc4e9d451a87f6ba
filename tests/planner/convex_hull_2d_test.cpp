// The 2D hull of the front cords (core/src/convex_hull_2d.h): thinning a large input by the hull
// of a subsample gives the same strict hull, bit for bit, and drops what is strictly inside.
#include "convex_hull_2d.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace cordgrasp::detail {
namespace {

constexpr int kSeeds = 20;
constexpr int kPoints = 3000;  // above kThinHullFromPoints, like a dense scan's section

/// A plane section of a bumpy scan: points along a wavy arc (radius 5 cm, bumps of 1 mm), each
/// twice (two segments share it), in a shuffled order, plus points strictly inside.
std::vector<Eigen::Vector2d> bumpy_section(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Eigen::Vector2d> pts;
  for (int k = 0; k < kPoints / 2; ++k) {
    const double a = M_PI * k / (kPoints / 2 - 1);
    const double r = 0.05 + 0.001 * std::sin(40.0 * a + seed) * u(rng);
    pts.emplace_back(r * std::cos(a), r * std::sin(a));
    pts.push_back(pts.back());
  }
  for (int k = 0; k < kPoints / 10; ++k) {
    const double a = M_PI * u(rng), r = 0.04 * u(rng);
    pts.emplace_back(r * std::cos(a), r * std::sin(a) + 1e-3);
  }
  std::shuffle(pts.begin(), pts.end(), rng);
  return pts;
}

TEST(ConvexHull2d, ThinnedLargeInputGivesTheSameHullBitForBit) {
  for (unsigned seed = 1; seed <= kSeeds; ++seed) {
    std::vector<Eigen::Vector2d> all = bumpy_section(seed), thinned = all, hull_all, hull, scratch;
    ASSERT_GE(all.size(), kThinHullFromPoints);
    convex_hull_ccw_all(all, hull_all);
    convex_hull_ccw(thinned, hull, scratch);
    EXPECT_LT(thinned.size(), all.size() / 3) << "seed " << seed << ": few points thinned";
    ASSERT_EQ(hull.size(), hull_all.size()) << "seed " << seed;
    for (size_t k = 0; k < hull.size(); ++k)
      EXPECT_TRUE(hull[k] == hull_all[k]) << "seed " << seed << ", hull vertex " << k;
  }
}

TEST(ConvexHull2d, PointsOnTheThinningHullsEdgesAreKept) {
  // A square and points along its sides: none is strictly inside, so none may be dropped
  // (a point on an edge can be a vertex of the hull of a larger set).
  const std::vector<Eigen::Vector2d> square = {{0.0, 0.0}, {0.1, 0.0}, {0.1, 0.1}, {0.0, 0.1}};
  std::vector<Eigen::Vector2d> pts = square;
  for (int k = 1; k < 100; ++k) {
    const double t = 0.001 * k;
    pts.insert(pts.end(), {{t, 0.0}, {0.1, t}, {t, 0.1}, {0.0, t}});
  }
  const size_t n = pts.size();
  std::vector<Eigen::Vector2d> poly = square;
  drop_points_inside_hull_of_some(pts, poly);
  EXPECT_EQ(pts.size(), n);
  pts.emplace_back(0.06, 0.03);   // strictly inside: dropped
  pts.emplace_back(0.05, 1e-15);  // inside by less than the margin: kept
  drop_points_inside_hull_of_some(pts, poly);
  EXPECT_EQ(pts.size(), n + 1);
  EXPECT_TRUE(pts.back() == Eigen::Vector2d(0.05, 1e-15));
}

TEST(ConvexHull2d, ThinningKeepsEveryVertexOfTheHull) {
  for (unsigned seed = 1; seed <= kSeeds; ++seed) {
    std::vector<Eigen::Vector2d> pts = bumpy_section(seed), sorted = pts, hull, sample;
    convex_hull_ccw_all(sorted, hull);
    for (size_t i = 0; i < pts.size(); i += kThinHullStride) sample.push_back(pts[i]);
    std::vector<Eigen::Vector2d> poly;
    convex_hull_ccw_all(sample, poly);
    drop_points_inside_hull_of_some(pts, poly);
    for (const Eigen::Vector2d& v : hull)
      EXPECT_NE(std::find(pts.begin(), pts.end(), v), pts.end()) << "seed " << seed;
  }
}

}  // namespace
}  // namespace cordgrasp::detail
