#include "cordgrasp/core/mesh_topology.h"

#include <gtest/gtest.h>

#include <cmath>

#include "cordgrasp/core/shape_builders.h"
#include "cordgrasp/core/shapes.h"

namespace cordgrasp {
namespace {

/// Every triangle gets its own three vertices (as STL stores them).
Mesh unshare_vertices(const Mesh& m) {
  Mesh out;
  for (const auto& t : m.triangles) {
    const int base = int(out.vertices.size());
    for (int k = 0; k < 3; ++k) out.vertices.push_back(m.vertices[t[k]]);
    out.triangles.emplace_back(base, base + 1, base + 2);
  }
  return out;
}

TEST(MeshTopology, ClosedBoxIsWatertightWithEulerCharacteristicTwo) {
  const MeshTopology t = mesh_topology(make_box_mesh({0.1, 0.2, 0.3}));
  EXPECT_TRUE(t.closed);
  EXPECT_EQ(t.vertices, 8);
  EXPECT_EQ(t.edges, 18);
  EXPECT_EQ(t.triangles, 12);
  EXPECT_EQ(t.boundary_edges, 0);
  EXPECT_EQ(t.non_manifold_edges, 0);
  EXPECT_EQ(t.misoriented_edges, 0);
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(t.euler_characteristic, 2);
}

TEST(MeshTopology, TorusHasEulerCharacteristicZero) {
  const MeshTopology t = mesh_topology(make_torus_mesh(0.05, 0.01, 20, 10));
  EXPECT_TRUE(t.closed);
  EXPECT_EQ(t.euler_characteristic, 0);
  EXPECT_EQ(t.components, 1);
}

TEST(MeshTopology, SoupWithOneVertexCopyPerTriangleIsWeldedBeforeCounting) {
  const Mesh grid = make_grid_box_mesh({0.05, 0.05, 0.08}, 0.01);
  const MeshTopology shared = mesh_topology(grid);
  const MeshTopology soup = mesh_topology(unshare_vertices(grid));
  EXPECT_TRUE(soup.closed);
  EXPECT_EQ(soup.vertices, shared.vertices);
  EXPECT_EQ(soup.edges, shared.edges);
  EXPECT_EQ(soup.components, 1);
  EXPECT_EQ(soup.euler_characteristic, 2);
}

TEST(MeshTopology, SignedZeroCopiesWeldAndAFanHubKeepsItsEdges) {
  // A box with a corner at the origin, one vertex copy per triangle, and the zero coordinates
  // of every other copy written as -0.0: -0.0 == +0.0, so the copies weld as before.
  Mesh box = make_box_mesh({0.1, 0.2, 0.3});
  Eigen::Vector3d corner = box.vertices[0];
  for (const auto& v : box.vertices) corner = corner.cwiseMin(v);
  for (auto& v : box.vertices) v -= corner;
  Mesh soup = unshare_vertices(box);
  for (size_t i = 0; i < soup.vertices.size(); i += 2)
    for (int c = 0; c < 3; ++c)
      if (soup.vertices[i][c] == 0.0) soup.vertices[i][c] = -0.0;
  const MeshTopology t = mesh_topology(soup);
  EXPECT_TRUE(t.closed);
  EXPECT_EQ(t.vertices, 8);
  EXPECT_EQ(t.edges, 18);
  EXPECT_EQ(t.misoriented_edges, 0);
  
  // A disk fanned from one hub vertex: the hub's edge bucket is large (> 32 entries).
  Mesh fan;
  fan.vertices.push_back(Eigen::Vector3d::Zero());
  const int rim = 100;
  for (int k = 0; k < rim; ++k)
    fan.vertices.emplace_back(std::cos(2 * M_PI * k / rim), std::sin(2 * M_PI * k / rim), 0.0);
  for (int k = 0; k < rim; ++k) fan.triangles.emplace_back(0, 1 + k, 1 + (k + 1) % rim);
  const MeshTopology f = mesh_topology(fan);
  EXPECT_EQ(f.vertices, rim + 1);
  EXPECT_EQ(f.edges, 2 * rim);
  EXPECT_EQ(f.boundary_edges, rim);
  EXPECT_EQ(f.misoriented_edges, 0);
  EXPECT_EQ(f.euler_characteristic, 1);
}

TEST(MeshTopology, MissingFaceLeavesBoundaryLoop) {
  Mesh box = make_box_mesh({1, 1, 1});
  box.triangles.resize(10);  // drop the last face (two triangles)
  const MeshTopology t = mesh_topology(box);
  EXPECT_FALSE(t.closed);
  EXPECT_EQ(t.boundary_edges, 4);
  EXPECT_EQ(t.non_manifold_edges, 0);
  EXPECT_EQ(t.euler_characteristic, 1);  // a disk
}

TEST(MeshTopology, FinOnBoxEdgeMakesThatEdgeNonManifold) {
  Mesh box = make_box_mesh({1, 1, 1});
  // Vertices 0 (−,−,−) and 4 (−,−,+) span a box edge; add a fin triangle on it.
  box.vertices.emplace_back(-1.0, -1.0, 0.0);
  box.triangles.emplace_back(0, 4, 8);
  const MeshTopology t = mesh_topology(box);
  EXPECT_FALSE(t.closed);
  EXPECT_EQ(t.non_manifold_edges, 1);
  EXPECT_EQ(t.boundary_edges, 2);
  EXPECT_EQ(t.components, 1);
}

TEST(MeshTopology, FlippedTriangleMisorientsItsThreeEdges) {
  Mesh box = make_grid_box_mesh({1, 1, 1}, 0.25);
  std::swap(box.triangles[5][1], box.triangles[5][2]);
  const MeshTopology t = mesh_topology(box);
  EXPECT_TRUE(t.closed);  // watertightness ignores winding
  EXPECT_EQ(t.misoriented_edges, 3);
}

TEST(MeshTopology, DisjointPartsAreSeparateComponents) {
  Mesh m = make_box_mesh({1, 1, 1});
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() = Eigen::Vector3d(3, 0, 0);
  append_mesh(m, make_sphere_mesh(0.5, 8, 12), X);
  const MeshTopology t = mesh_topology(m);
  EXPECT_EQ(t.components, 2);
  EXPECT_EQ(t.euler_characteristic, 4);
  EXPECT_TRUE(t.closed);
}

TEST(MeshTopology, EmptyMeshIsNotClosed) {
  const MeshTopology t = mesh_topology(Mesh{});
  EXPECT_FALSE(t.closed);
  EXPECT_EQ(t.components, 0);
}

}  // namespace
}  // namespace cordgrasp
