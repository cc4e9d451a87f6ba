// Primitive A (plane cross-section) and Primitive B (segment–mesh hits): the BVH forms agree
// with brute force.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <numeric>
#include <random>
#include <tuple>

#include "cord_test_util.h"
#include "cordgrasp/core/mesh_bvh.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/plane_cross_section.h"
#include "cordgrasp/core/segment_mesh_hits.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

using Key = std::tuple<double, double, double, double>;

std::vector<Key> sorted_keys(const std::vector<Segment2>& segments) {
  std::vector<Key> keys;
  for (const Segment2& s : segments) keys.emplace_back(s.a.x(), s.a.y(), s.b.x(), s.b.y());
  std::sort(keys.begin(), keys.end());
  return keys;
}

PlaneFrame random_plane_through(const Mesh& mesh, std::mt19937_64& rng) {
  const CordObject object = make_cord_object(mesh);
  const test::GuideTriangle t = test::random_guide_triangle(object, rng);
  return guide_frame(t.p1, t.p2, t.p3);
}

void expect_bvh_matches_brute_force(const Mesh& mesh, int planes, std::mt19937_64& rng) {
  const MeshBvh bvh = build_mesh_bvh(mesh);
  for (int k = 0; k < planes; ++k) {
    const PlaneFrame plane = random_plane_through(mesh, rng);
    const CrossSection brute = plane_cross_section(mesh, plane);
    const CrossSection fast = plane_cross_section(bvh, plane);
    // Same arithmetic on the same triangles: bit-identical segments.
    ASSERT_EQ(sorted_keys(brute.segments), sorted_keys(fast.segments)) << mesh.name;
    EXPECT_EQ(brute.points.size(), fast.points.size()) << mesh.name;
    std::vector<Segment2> appended;
    append_plane_cross_section_segments(bvh, plane, appended);
    EXPECT_EQ(sorted_keys(brute.segments), sorted_keys(appended)) << mesh.name;
  }
}

TEST(PlaneCrossSection, BvhMatchesBruteForceOnRandomPlanes) {
  std::mt19937_64 rng(7);
  for (const Mesh& mesh : test::test_shapes()) expect_bvh_matches_brute_force(mesh, 40, rng);
}

TEST(MeshBvh, NodeBoxesAreExactlyTheBoundsOfTheirTriangles) {
  // Boxes are built bottom-up (union of children); each must equal the min/max of the corners
  // of the triangles below it, computed directly. Random soup, seeded.
  std::mt19937_64 rng(40);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  Mesh soup;
  for (int k = 0; k < 3000; ++k) soup.vertices.emplace_back(u(rng), u(rng), u(rng));
  std::uniform_int_distribution<int> pick(0, 2999);
  for (int k = 0; k < 5000; ++k) soup.triangles.emplace_back(pick(rng), pick(rng), pick(rng));
  for (const MeshBvhSplit split : {MeshBvhSplit::kCentroidThenIndex, MeshBvhSplit::kCornerSum}) {
    const MeshBvh bvh = build_mesh_bvh(soup, 4, split);
    // Triangle range [first, end) of each node's subtree (leaves are contiguous in order).
    std::vector<std::pair<int, int>> range(bvh.nodes.size());
    for (int i = int(bvh.nodes.size()) - 1; i >= 0; --i) {
      const MeshBvh::Node& n = bvh.nodes[size_t(i)];
      range[size_t(i)] = n.count > 0 ? std::make_pair(n.first, n.first + n.count)
                                     : std::make_pair(range[size_t(i) + 1].first,
                                                      range[size_t(n.first)].second);
    }
    for (size_t i = 0; i < bvh.nodes.size(); ++i) {
      Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
      for (int k = range[i].first; k < range[i].second; ++k)
        for (int c = 0; c < 3; ++c) {
          lo = lo.cwiseMin(bvh.vertices[size_t(bvh.triangles[size_t(k)][c])]);
          hi = hi.cwiseMax(bvh.vertices[size_t(bvh.triangles[size_t(k)][c])]);
        }
      ASSERT_EQ(bvh.nodes[i].lo, lo) << "node " << i;
      ASSERT_EQ(bvh.nodes[i].hi, hi) << "node " << i;
    }
    EXPECT_EQ(range[0], std::make_pair(0, 5000));
  }
}

TEST(MeshBvh, ObjectBvhDropsZeroAreaTrianglesAndIndexesTheMeshTriangles) {
  // A box with a zero-area triangle (repeated corner) and a sliver of collinear corners
  // inserted between its faces.
  Mesh mesh = make_box_mesh(Eigen::Vector3d(0.04, 0.03, 0.02));
  const int n = static_cast<int>(mesh.triangles.size());
  mesh.vertices.emplace_back(0.0, 0.0, 0.0);
  mesh.vertices.emplace_back(0.01, 0.0, 0.0);
  mesh.vertices.emplace_back(0.02, 0.0, 0.0);
  const int v = static_cast<int>(mesh.vertices.size()) - 3;
  mesh.triangles.insert(mesh.triangles.begin() + 3, Eigen::Vector3i(0, 1, 1));
  mesh.triangles.insert(mesh.triangles.begin() + 7, Eigen::Vector3i(v, v + 1, v + 2));
  const MeshBvh bvh = build_object_bvh(mesh);
  ASSERT_EQ(static_cast<int>(bvh.triangles.size()), n);
  std::vector<int> ids = bvh.triangle_ids;
  for (size_t k = 0; k < bvh.triangles.size(); ++k)
    EXPECT_EQ(bvh.triangles[k], mesh.triangles[static_cast<size_t>(bvh.triangle_ids[k])]) << k;
  std::sort(ids.begin(), ids.end());
  EXPECT_TRUE(std::adjacent_find(ids.begin(), ids.end()) == ids.end());
  EXPECT_TRUE(std::find(ids.begin(), ids.end(), 3) == ids.end());  // the zero-area ones
  EXPECT_TRUE(std::find(ids.begin(), ids.end(), 7) == ids.end());
}

TEST(MeshBvh, ObjectBvhOfALargeScanHasAQuarterOfTheNodes) {
  // Above kLargeMeshTriangles the shared BVH keeps up to kLargeMeshLeafTriangles per leaf:
  // its nodes (64 B each) are the bulk of a scan's memory. A 250 k-triangle grid sphere.
  const Mesh small = make_sphere_mesh(0.05, 50, 100);
  const Mesh large = make_sphere_mesh(0.05, 350, 360);
  ASSERT_LE(static_cast<int>(small.triangles.size()), kLargeMeshTriangles);
  ASSERT_GT(static_cast<int>(large.triangles.size()), kLargeMeshTriangles);
  const MeshBvh s = build_object_bvh(small), l = build_object_bvh(large);
  EXPECT_GT(s.nodes.size(), small.triangles.size() / 2);
  EXPECT_LT(l.nodes.size(), large.triangles.size() / 4);
  int largest_leaf = 0;
  for (const MeshBvh::Node& n : l.nodes) largest_leaf = std::max(largest_leaf, n.count);
  EXPECT_LE(largest_leaf, kLargeMeshLeafTriangles);
  EXPECT_EQ(l.triangles.size(), large.triangles.size());
}

void expect_same_bvh(const MeshBvh& one, const MeshBvh& two) {
  ASSERT_EQ(one.nodes.size(), two.nodes.size());
  for (size_t k = 0; k < one.nodes.size(); ++k) {
    ASSERT_EQ(one.nodes[k].lo, two.nodes[k].lo) << k;
    ASSERT_EQ(one.nodes[k].hi, two.nodes[k].hi) << k;
    ASSERT_EQ(one.nodes[k].radius, two.nodes[k].radius) << k;
    ASSERT_EQ(one.nodes[k].first, two.nodes[k].first) << k;
    ASSERT_EQ(one.nodes[k].count, two.nodes[k].count) << k;
  }
  EXPECT_EQ(one.triangle_ids, two.triangle_ids);
  EXPECT_EQ(one.triangles, two.triangles);
  EXPECT_EQ(one.vertices, two.vertices);
}

TEST(MeshBvh, ObjectBvhOfALargeScanIsTheSameBuiltOnTwoThreads) {
  const Mesh scan = make_sphere_mesh(0.05, 350, 360);
  ASSERT_GT(static_cast<int>(scan.triangles.size()), kLargeMeshTriangles);
  expect_same_bvh(build_object_bvh(scan, 1), build_object_bvh(scan, 2));
  // With zero-area triangles in both halves of the triangle list (dropped, the rest indexed).
  Mesh soup = scan;
  const int half = static_cast<int>(soup.triangles.size()) / 2;
  soup.triangles.insert(soup.triangles.begin() + half + 7, Eigen::Vector3i(4, 4, 5));
  soup.triangles.insert(soup.triangles.begin() + 11, Eigen::Vector3i(1, 2, 2));
  const MeshBvh one = build_object_bvh(soup, 1), two = build_object_bvh(soup, 2);
  expect_same_bvh(one, two);
  EXPECT_EQ(two.triangles.size(), scan.triangles.size());
  for (size_t k = 0; k < two.triangles.size(); ++k)
    for (int c = 0; c < 3; ++c)
      ASSERT_EQ(two.vertices[static_cast<size_t>(two.triangles[k][c])],
                soup.vertices[static_cast<size_t>(
                    soup.triangles[static_cast<size_t>(two.triangle_ids[k])][c])])
          << k;
}

TEST(MeshBvh, ObjectBvhOfALargeScanNumbersItsVerticesAlongTheLeaves) {
  // A scan's vertices listed in a scattered order: the BVH's copy is renumbered in first use
  // along its leaves, and every BVH triangle keeps the corners of the mesh triangle it names.
  Mesh scan = make_sphere_mesh(0.05, 350, 360);
  ASSERT_GT(static_cast<int>(scan.triangles.size()), kLargeMeshTriangles);
  std::vector<int> order(scan.vertices.size());
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937_64(5));
  std::vector<Eigen::Vector3d> scattered(scan.vertices.size());
  for (size_t i = 0; i < order.size(); ++i) scattered[size_t(order[i])] = scan.vertices[i];
  for (Eigen::Vector3i& t : scan.triangles)
    for (int k = 0; k < 3; ++k) t[k] = order[size_t(t[k])];
  scan.vertices = scattered;
  const MeshBvh bvh = build_object_bvh(scan);
  ASSERT_EQ(bvh.triangles.size(), scan.triangles.size());
  EXPECT_EQ(bvh.vertices.size(), scan.vertices.size());
  int next = 0;  // first uses come in order 0, 1, 2, ...
  for (size_t k = 0; k < bvh.triangles.size(); ++k) {
    const Eigen::Vector3i& t = bvh.triangles[k];
    const Eigen::Vector3i& m = scan.triangles[static_cast<size_t>(bvh.triangle_ids[k])];
    for (int c = 0; c < 3; ++c) {
      ASSERT_EQ(bvh.vertices[size_t(t[c])], scan.vertices[size_t(m[c])]) << k;
      ASSERT_LE(t[c], next) << k;
      if (t[c] == next) ++next;
    }
  }
}

TEST(PlaneCrossSection, SharedEdgesGiveOnePointPerCrossingOfAClosedSurface) {
  // A closed manifold: every crossing point is shared by exactly two segments.
  const Mesh sphere = make_sphere_mesh(0.04, 16, 32);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> offset(-0.03, 0.03);
  for (int k = 0; k < 20; ++k) {
    const Eigen::Vector3d n = test::random_unit(rng);
    const Eigen::Vector3d e1 = n.unitOrthogonal();
    PlaneFrame plane{offset(rng) * n, e1, n.cross(e1), n};
    const CrossSection cs = plane_cross_section(sphere, plane);
    ASSERT_FALSE(cs.segments.empty());
    EXPECT_EQ(cs.points.size(), cs.segments.size());
  }
}

TEST(PlaneCrossSection, BoxSectionIsItsSquareOutline) {
  constexpr double kTol_m = 1e-15;
  const Mesh box = make_box_mesh(Eigen::Vector3d(0.04, 0.04, 0.04));
  PlaneFrame plane;
  plane.origin = Eigen::Vector3d(0.0, 0.0, 0.003);
  const CrossSection cs = plane_cross_section(box, plane);
  double perimeter = 0.0;
  for (const Segment2& s : cs.segments) {
    perimeter += (s.b - s.a).norm();
    for (const Eigen::Vector2d& p : {s.a, s.b})
      EXPECT_NEAR(p.cwiseAbs().maxCoeff(), 0.02, kTol_m);  // on the square's outline
  }
  EXPECT_NEAR(perimeter, 0.16, 1e-12);
}

TEST(SegmentMeshHits, BvhMatchesBruteForceOnRandomSegments) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-0.08, 0.08);
  for (const Mesh& mesh : test::test_shapes()) {
    const MeshBvh bvh = build_mesh_bvh(mesh);
    for (int k = 0; k < 200; ++k) {
      const Eigen::Vector3d a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
      const std::vector<SegmentHit> brute = segment_mesh_hits(mesh, a, b);
      const std::vector<SegmentHit> fast = segment_mesh_hits(bvh, a, b);
      ASSERT_EQ(brute.size(), fast.size()) << mesh.name;
      for (size_t h = 0; h < brute.size(); ++h) EXPECT_EQ(brute[h].t, fast[h].t);
      const double len = (b - a).norm();
      const bool interior_hit = std::any_of(brute.begin(), brute.end(), [&](const SegmentHit& h) {
        return h.t * len > 1e-9 && (1.0 - h.t) * len > 1e-9;
      });
      EXPECT_EQ(segment_meets_mesh(bvh, a, b), interior_hit);
    }
  }
}

TEST(SegmentMeshHits, ThroughABoxHitsBothFacesInOrder) {
  constexpr double kTol = 1e-12;
  const Mesh box = make_box_mesh(Eigen::Vector3d(0.04, 0.04, 0.04));
  const std::vector<SegmentHit> hits = segment_mesh_hits(box, Eigen::Vector3d(-0.1, 0.003, 0.001),
                                                         Eigen::Vector3d(0.1, 0.003, 0.001));
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_NEAR(hits[0].point.x(), -0.02, kTol);
  EXPECT_NEAR(hits[1].point.x(), 0.02, kTol);
}

TEST(CrossSectionDataset, BvhMatchesBruteForceOnSharedObjects) {
  CORDGRASP_REQUIRE_SHARED_DATA();
  std::mt19937_64 rng(5);
  for (const std::string dir : {"kit", "ycb", "simox"})
    for (const std::string& path :
         test::files_in(test::shared_data_dir() + "/objects/" + dir, ".obj"))
      expect_bvh_matches_brute_force(load_mesh(path), 5, rng);
}

}  // namespace
}  // namespace cordgrasp
