#include "cordgrasp/core/mesh_volume.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "cordgrasp/core/convex_hull_volume.h"
#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/core/orient_triangles.h"
#include "cordgrasp/core/shape_builders.h"
#include "cordgrasp/core/shapes.h"

namespace cordgrasp {
namespace {

constexpr double kVolTol_m3 = 1e-15;
constexpr double kPosTol_m = 1e-12;

Eigen::Isometry3d random_pose(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.rotate(Eigen::Quaterniond(u(rng), u(rng), u(rng), u(rng)).normalized());
  X.translation() = Eigen::Vector3d(u(rng), u(rng), u(rng));
  return X;
}

Mesh transformed(const Mesh& m, const Eigen::Isometry3d& X) {
  Mesh out;
  append_mesh(out, m, X);
  return out;
}

TEST(ClosedMeshVolume, BoxVolumeAndCentreAreExact) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() = Eigen::Vector3d(0.3, -0.2, 0.1);
  const auto v = closed_mesh_volume(transformed(make_box_mesh({0.1, 0.2, 0.3}), X));
  ASSERT_TRUE(v.has_value());
  EXPECT_NEAR(v->volume_m3, 0.006, kVolTol_m3);
  EXPECT_TRUE(v->center_of_mass_m.isApprox(X.translation(), kPosTol_m));
}

TEST(ClosedMeshVolume, InvariantUnderRigidMotionsAndCentreMovesWithTheMesh) {
  const Mesh torus = make_torus_mesh(0.05, 0.015, 24, 12);
  const auto ref = closed_mesh_volume(torus);
  ASSERT_TRUE(ref.has_value());
  std::mt19937_64 rng(7);
  for (int i = 0; i < 20; ++i) {
    const Eigen::Isometry3d X = random_pose(rng);
    const auto v = closed_mesh_volume(transformed(torus, X));
    ASSERT_TRUE(v.has_value());
    EXPECT_NEAR(v->volume_m3, ref->volume_m3, 1e-12 * ref->volume_m3);
    EXPECT_LT((v->center_of_mass_m - X * ref->center_of_mass_m).norm(), 1e-12);
  }
}

TEST(ClosedMeshVolume, FlippedFacesAndInsideOutMeshesGiveTheSamePositiveVolume) {
  const Mesh sphere = make_sphere_mesh(0.05, 12, 24);
  const auto ref = closed_mesh_volume(sphere);
  ASSERT_TRUE(ref.has_value());
  EXPECT_GT(ref->volume_m3, 0.0);
  Mesh inside_out = sphere;
  for (auto& t : inside_out.triangles) std::swap(t[1], t[2]);
  Mesh some_flipped = sphere;
  std::mt19937_64 rng(3);
  for (auto& t : some_flipped.triangles)
    if (rng() % 3 == 0) std::swap(t[0], t[1]);
  for (const Mesh& m : {inside_out, some_flipped}) {
    const auto v = closed_mesh_volume(m);
    ASSERT_TRUE(v.has_value());
    EXPECT_NEAR(v->volume_m3, ref->volume_m3, 1e-15);
    EXPECT_LT(v->center_of_mass_m.norm(), kPosTol_m);
  }
}

TEST(ClosedMeshVolume, SoupOfClosedPartsSumsVolumesAndWeightsCentres) {
  Mesh m = make_box_mesh({1, 1, 1});
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() = Eigen::Vector3d(3, 0, 0);
  Mesh big = make_box_mesh({2, 2, 2});
  for (auto& t : big.triangles) std::swap(t[1], t[2]);  // this part authored inside out
  append_mesh(m, big, X);
  const auto v = closed_mesh_volume(m);
  ASSERT_TRUE(v.has_value());
  EXPECT_NEAR(v->volume_m3, 9.0, 1e-12);
  EXPECT_NEAR(v->center_of_mass_m.x(), 3.0 * 8.0 / 9.0, 1e-12);
}

TEST(ClosedMeshVolume, EmptyForOpenOrNonManifoldMeshes) {
  Mesh open = make_box_mesh({1, 1, 1});
  open.triangles.pop_back();
  EXPECT_FALSE(closed_mesh_volume(open).has_value());
  Mesh fin = make_box_mesh({1, 1, 1});
  fin.vertices.emplace_back(-1.0, -1.0, 0.0);
  fin.triangles.emplace_back(0, 4, 8);
  fin.triangles.emplace_back(0, 8, 4);  // a double-sided fin: no boundary, but non-manifold
  EXPECT_FALSE(closed_mesh_volume(fin).has_value());
  EXPECT_FALSE(closed_mesh_volume(Mesh{}).has_value());
}

TEST(OrientTriangles, RestoresOutwardWindingOfAClosedSoup) {
  const Mesh ref = make_grid_box_mesh({0.05, 0.05, 0.08}, 0.01);
  Mesh m = ref;
  const std::vector<int> flipped{0, 7, 100, 333};
  for (int i : flipped) std::swap(m.triangles[i][0], m.triangles[i][1]);
  const OrientReport r = orient_triangles(m);
  EXPECT_TRUE(r.orientable);
  EXPECT_EQ(r.flipped, int(flipped.size()));
  EXPECT_EQ(r.patches, 1);
  EXPECT_EQ(r.closed_patches, 1);
  for (size_t t = 0; t < m.triangles.size(); ++t) {
    // Same cyclic order as the reference triangle.
    const auto& a = m.triangles[t];
    const auto& b = ref.triangles[t];
    const bool same = (a == b) || (a == Eigen::Vector3i(b[1], b[2], b[0])) ||
                      (a == Eigen::Vector3i(b[2], b[0], b[1]));
    EXPECT_TRUE(same) << "triangle " << t;
  }
}

TEST(OrientTriangles, OpenPatchKeepsTheWindingOfMostTriangles) {
  Mesh m = make_box_mesh({1, 1, 1});
  m.triangles.resize(10);
  std::swap(m.triangles[3][1], m.triangles[3][2]);
  const OrientReport r = orient_triangles(m);
  EXPECT_EQ(r.flipped, 1);
  EXPECT_EQ(r.closed_patches, 0);
}

TEST(OrientTriangles, MoebiusStripIsNotOrientable) {
  // Strip of n quads whose ends are glued with a half twist.
  const int n = 12;
  Mesh m;
  for (int i = 0; i < n; ++i) {
    const double u = 2 * M_PI * i / n;
    for (int s = -1; s <= 1; s += 2) {
      const double w = 0.3 * s, c = std::cos(u / 2), sn = std::sin(u / 2);
      m.vertices.emplace_back((1 + w * c) * std::cos(u), (1 + w * c) * std::sin(u), w * sn);
    }
  }
  for (int i = 0; i < n; ++i) {
    const int a = 2 * i, b = 2 * i + 1;
    int c = 2 * (i + 1), d = 2 * (i + 1) + 1;
    if (i == n - 1) {  // the half twist: the last quad meets the first pair reversed
      c = 1;
      d = 0;
    }
    m.triangles.emplace_back(a, c, d);
    m.triangles.emplace_back(a, d, b);
  }
  EXPECT_FALSE(orient_triangles(m).orientable);
}

TEST(ConvexHullVolume, ConvexMeshHullEqualsItsClosedVolume) {
  for (const Mesh& m : {make_box_mesh({0.05, 0.07, 0.11}), make_sphere_mesh(0.03, 10, 20),
                        make_cylinder_mesh(0.02, 0.2, 24)}) {
    const SolidVolume hull = convex_hull_volume(m);
    const auto solid = closed_mesh_volume(m);
    ASSERT_TRUE(solid.has_value());
    EXPECT_NEAR(hull.volume_m3, solid->volume_m3, 1e-12 * solid->volume_m3);
    EXPECT_LT((hull.center_of_mass_m - solid->center_of_mass_m).norm(), 1e-12);
  }
}

TEST(ConvexHullVolume, TetrahedronOfRandomPointsMatchesDeterminant) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  for (int i = 0; i < 20; ++i) {
    Mesh m;
    for (int k = 0; k < 4; ++k) m.vertices.emplace_back(u(rng), u(rng), u(rng));
    m.triangles = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
    const double expected =
        std::abs((m.vertices[1] - m.vertices[0])
                     .dot((m.vertices[2] - m.vertices[0]).cross(m.vertices[3] - m.vertices[0]))) /
        6.0;
    const Eigen::Vector3d centroid =
        0.25 * (m.vertices[0] + m.vertices[1] + m.vertices[2] + m.vertices[3]);
    const SolidVolume hull = convex_hull_volume(m);
    EXPECT_NEAR(hull.volume_m3, expected, 1e-12 * expected);
    EXPECT_LT((hull.center_of_mass_m - centroid).norm(), 1e-12);
  }
}

TEST(ConvexHullVolume, NonConvexAndOpenMeshesGetTheirHull) {
  // A torus's hull is the cylinder-like solid around it: bigger than the torus itself.
  const Mesh torus = make_torus_mesh(0.04, 0.012, 48, 24);
  EXPECT_GT(convex_hull_volume(torus).volume_m3, 1.5 * closed_mesh_volume(torus)->volume_m3);
  // An open box (one face missing) still has the box as hull.
  Mesh open = make_box_mesh({0.1, 0.2, 0.3});
  open.triangles.resize(10);
  EXPECT_NEAR(convex_hull_volume(open).volume_m3, 0.006, 1e-15);
}

TEST(ColumnExtremePoints, KeepTheHullOfADenseScanWithinTheirBound) {
  // A bumpy sphere of 320 k vertices, a scan's density: the column extremes on a 64-cell grid
  // are a few per cent of the points, in input order, and their hull reaches every direction's
  // farthest point to within √2 cell widths (the bound column_extreme_points states).
  Mesh scan = make_sphere_mesh(0.05, 400, 800);
  for (Eigen::Vector3d& v : scan.vertices)
    v *= 1.0 + 0.02 * std::sin(40.0 * v.x() / 0.05) * std::cos(30.0 * v.z() / 0.05);
  constexpr int kCells = 64;
  const std::vector<Eigen::Vector3d> kept = column_extreme_points(scan.vertices, kCells);
  ASSERT_GE(kept.size(), 4u);
  EXPECT_LE(kept.size(), size_t(6 * kCells * kCells));
  EXPECT_LT(kept.size(), scan.vertices.size() / 10);
  size_t next = 0;  // a subsequence of the input
  for (const Eigen::Vector3d& p : kept) {
    while (next < scan.vertices.size() && scan.vertices[next] != p) ++next;
    ASSERT_LT(next, scan.vertices.size());
    ++next;
  }
  const Eigen::Vector3d size = mesh_bounds(scan).size();
  const double bound_m = std::sqrt(2.0) * size.maxCoeff() / kCells;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> g;
  for (int k = 0; k < 200; ++k) {
    const Eigen::Vector3d d = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
    double all = -1e9, some = -1e9;
    for (const Eigen::Vector3d& v : scan.vertices) all = std::max(all, d.dot(v));
    for (const Eigen::Vector3d& v : kept) some = std::max(some, d.dot(v));
    EXPECT_LE(some, all);
    EXPECT_GE(some, all - bound_m) << k;
  }
  const double exact = convex_hull_volume(scan).volume_m3;
  const double reduced = convex_hull_volume(kept).volume_m3;
  EXPECT_LE(reduced, exact * (1.0 + 1e-12));
  EXPECT_GE(reduced, 0.99 * exact);
}

TEST(ColumnExtremePoints, FewPointsOrNoGridAreKeptAsTheyAre) {
  const std::vector<Eigen::Vector3d> three = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_EQ(column_extreme_points(three, 8), three);
  const std::vector<Eigen::Vector3d> same(5, Eigen::Vector3d(0.1, 0.2, 0.3));
  EXPECT_EQ(column_extreme_points(same, 8), same);  // no extent: no grid
}

TEST(ConvexHullVolume, FlatOrTinyInputGivesZeroVolumeAndVertexMean) {
  Mesh quad;
  quad.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  quad.triangles = {{0, 1, 2}, {0, 2, 3}};
  const SolidVolume flat = convex_hull_volume(quad);
  EXPECT_EQ(flat.volume_m3, 0.0);
  EXPECT_TRUE(flat.center_of_mass_m.isApprox(Eigen::Vector3d(0.5, 0.5, 0.0)));
  Mesh tri;
  tri.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  tri.triangles = {{0, 1, 2}};
  EXPECT_EQ(convex_hull_volume(tri).volume_m3, 0.0);
  EXPECT_EQ(convex_hull_volume(Mesh{}).volume_m3, 0.0);
}

}  // namespace
}  // namespace cordgrasp
