#include "cordgrasp/core/shape_builders.h"

#include <gtest/gtest.h>

#include <cmath>

#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/core/mesh_topology.h"
#include "cordgrasp/core/mesh_volume.h"
#include "cordgrasp/core/orient_triangles.h"

namespace cordgrasp {
namespace {

constexpr double kRelTol = 1e-12;

/// Signed volume by the divergence theorem: positive iff the triangles face outward.
double signed_volume(const Mesh& m) {
  double v = 0;
  for (const auto& t : m.triangles)
    v += m.vertices[t[0]].dot(m.vertices[t[1]].cross(m.vertices[t[2]])) / 6.0;
  return v;
}

/// Volume of the prism over a regular n-gon inscribed in radius r.
double prism_volume(double r, double length, int n) {
  return 0.5 * n * r * r * std::sin(2 * M_PI / n) * length;
}

TEST(MakeRevolvedMesh, CylinderProfileGivesClosedOutwardPrism) {
  const int n = 30;
  const Mesh m = make_revolved_mesh({{0, 0}, {0.02, 0}, {0.02, 0.1}, {0.02, 0.2}, {0, 0.2}}, n);
  const MeshTopology t = mesh_topology(m);
  EXPECT_TRUE(t.closed);
  EXPECT_EQ(t.euler_characteristic, 2);
  EXPECT_EQ(t.misoriented_edges, 0);
  EXPECT_NEAR(signed_volume(m), prism_volume(0.02, 0.2, n), kRelTol * 1e-4);
  EXPECT_EQ(int(m.triangles.size()), 6 * n);  // 2 pole rows of n + 2 side rows of 2n
}

TEST(MakeRevolvedMesh, HollowShellProfileIsClosedAndOutward) {
  // A cup: outside up, rim, inside down, bottom to the axis.
  const Mesh m = make_revolved_mesh(
      {{0, 0}, {0.04, 0}, {0.04, 0.1}, {0.036, 0.1}, {0.036, 0.006}, {0, 0.006}}, 40);
  EXPECT_TRUE(mesh_topology(m).closed);
  const double expected = prism_volume(0.04, 0.1, 40) - prism_volume(0.036, 0.094, 40);
  EXPECT_NEAR(signed_volume(m), expected, 1e-15);
}

TEST(MakeRevolvedMesh, ProfileEndingOffTheAxisLeavesAnOpenRim) {
  const Mesh m = make_revolved_mesh({{0, 0}, {0.03, 0}, {0.03, 0.05}}, 24);
  const MeshTopology t = mesh_topology(m);
  EXPECT_FALSE(t.closed);
  EXPECT_EQ(t.boundary_edges, 24);
}

TEST(MakeRevolvedMesh, RejectsBadProfiles) {
  EXPECT_THROW(make_revolved_mesh({{0, 0}}, 12), std::invalid_argument);
  EXPECT_THROW(make_revolved_mesh({{0, 0}, {-0.1, 1}}, 12), std::invalid_argument);
  EXPECT_THROW(make_revolved_mesh({{0, 0}, {0.1, 1}}, 2), std::invalid_argument);
}

TEST(MakeSweptTubeMesh, StraightTubeIsAClosedOutwardPrism) {
  const int n = 16;
  const Mesh m = make_swept_tube_mesh({{0, 0, 0}, {0.05, 0.05, 0.05}, {0.1, 0.1, 0.1}}, 0.01, n);
  EXPECT_TRUE(mesh_topology(m).closed);
  EXPECT_NEAR(signed_volume(m), prism_volume(0.01, std::sqrt(0.03), n), 1e-15);
}

TEST(MakeSweptTubeMesh, BentTubeVolumeFollowsPappus) {
  // Quarter circle of radius 0.1; Pappus: volume = cross-section area × centre-line length.
  std::vector<Eigen::Vector3d> path;
  const int steps = 64;
  for (int i = 0; i <= steps; ++i) {
    const double a = 0.5 * M_PI * i / steps;
    path.emplace_back(0.1 * std::cos(a), 0.1 * std::sin(a), 0.0);
  }
  const int n = 32;
  Mesh m = make_swept_tube_mesh(path, 0.01, n);
  const MeshTopology t = mesh_topology(m);
  EXPECT_TRUE(t.closed);
  EXPECT_EQ(t.misoriented_edges, 0);
  const double expected = prism_volume(0.01, 0.5 * M_PI * 0.1, n);
  EXPECT_NEAR(signed_volume(m), expected, 1e-3 * expected);
  EXPECT_EQ(orient_triangles(m).flipped, 0);  // already outward
}

TEST(MakeSweptTubeMesh, TaperedTubeIsAFrustum) {
  const int n = 24;
  const std::vector<double> radii{0.02, 0.01};
  const Mesh m = make_swept_tube_mesh({{0, 0, 0}, {0, 0, 0.1}}, radii, n);
  // Frustum of regular n-gons: h/3 (A1 + A2 + sqrt(A1 A2)).
  const double a1 = prism_volume(0.02, 1, n), a2 = prism_volume(0.01, 1, n);
  EXPECT_NEAR(signed_volume(m), 0.1 / 3 * (a1 + a2 + std::sqrt(a1 * a2)), 1e-15);
}

TEST(MakeSweptTubeMesh, RejectsBadInput) {
  EXPECT_THROW(make_swept_tube_mesh({{0, 0, 0}}, 0.01), std::invalid_argument);
  EXPECT_THROW(make_swept_tube_mesh({{0, 0, 0}, {0, 0, 0}}, 0.01), std::invalid_argument);
  EXPECT_THROW(make_swept_tube_mesh({{0, 0, 0}, {0, 0, 1}}, std::vector<double>{0.1}),
               std::invalid_argument);
}

TEST(MakeGridBoxMesh, IsClosedOutwardWithExactVolumeAndSharedLattice) {
  const Mesh m = make_grid_box_mesh({0.05, 0.05, 0.08}, 0.01);
  const MeshTopology t = mesh_topology(m);
  EXPECT_TRUE(t.closed);
  EXPECT_EQ(t.euler_characteristic, 2);
  EXPECT_EQ(t.misoriented_edges, 0);
  // Surface lattice points of a 5×5×8 cell grid.
  EXPECT_EQ(int(m.vertices.size()), 6 * 6 * 9 - 4 * 4 * 7);
  EXPECT_EQ(int(m.triangles.size()), 4 * (25 + 40 + 40));
  EXPECT_NEAR(signed_volume(m), 0.05 * 0.05 * 0.08, 1e-15);
  EXPECT_TRUE(mesh_bounds(m).size().isApprox(Eigen::Vector3d(0.05, 0.05, 0.08)));
}

TEST(DensifyPolyline, KeepsCornersAndBoundsStep) {
  const auto out = densify_polyline({{0, 0}, {0.1, 0}, {0.1, 0.025}}, 0.03);
  ASSERT_EQ(out.size(), 6u);  // 4 steps then 1
  EXPECT_EQ(out.front(), Eigen::Vector2d(0, 0));
  EXPECT_EQ(out[4], Eigen::Vector2d(0.1, 0));
  for (size_t i = 1; i < out.size(); ++i) EXPECT_LE((out[i] - out[i - 1]).norm(), 0.03);
}

}  // namespace
}  // namespace cordgrasp
