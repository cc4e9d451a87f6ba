// Hull vertices from Qhull and their reduction: the path the object body takes for raw scans.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "cordgrasp/core/convex_hull_volume.h"
#include "cordgrasp/core/mesh_volume.h"
#include "cordgrasp/core/object_meshes.h"
#include "cordgrasp/core/shapes.h"
#include "cordgrasp/core/sphere_points.h"
#include "cordgrasp/sim/convex_decomposition.h"

namespace cordgrasp {
namespace {

constexpr int kMaxHullVertices = 64;
constexpr int kSeparatingDirections = 2000;  // tried per (point, part)
constexpr double kOutsideMargin_m = 1e-3;    // a cavity point lies this far outside a part

/// True when a direction among kSeparatingDirections puts `p` more than kOutsideMargin_m beyond
/// every vertex of the convex part: `p` is then outside the part's hull (a sufficient test).
bool outside_hull(const std::vector<Eigen::Vector3d>& part, const Eigen::Vector3d& p) {
  static const std::vector<Eigen::Vector3d> directions =
      sphere_points(kSeparatingDirections, SphereSequence::kFibonacci);
  for (const Eigen::Vector3d& d : directions) {
    double reach = -std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3d& v : part) reach = std::max(reach, d.dot(v));
    if (d.dot(p) > reach + kOutsideMargin_m) return true;
  }
  return false;
}

bool contains(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& p) {
  return std::find(points.begin(), points.end(), p) != points.end();
}

TEST(ConvexHullVertices, AreTheCornersOfABoxAndEveryPointOfASphere) {
  std::vector<Eigen::Vector3d> box_hull, sphere_hull;
  const Mesh box = make_box_mesh(Eigen::Vector3d(0.02, 0.04, 0.06));
  convex_hull_volume(box, &box_hull);
  EXPECT_EQ(box_hull.size(), 8u);
  for (const Eigen::Vector3d& p : box_hull) EXPECT_TRUE(contains(box.vertices, p));
  const Mesh sphere = make_sphere_mesh(0.03, 12, 24);
  const SolidVolume v = convex_hull_volume(sphere, &sphere_hull);
  EXPECT_EQ(sphere_hull.size(), sphere.vertices.size());
  EXPECT_GT(v.volume_m3, 0.0);
}

TEST(ReducedConvexHull, KeepsAtMostTheBoundFromTheHullVerticesAsTheFullPathDoes) {
  const Mesh sphere = make_sphere_mesh(0.03, 24, 48);
  std::vector<Eigen::Vector3d> hull;
  convex_hull_volume(sphere, &hull);
  const std::vector<Eigen::Vector3d> reduced = reduced_convex_hull(hull, kMaxHullVertices);
  const std::vector<Eigen::Vector3d> full =
      simplified_convex_hull(sphere.vertices, kMaxHullVertices);
  EXPECT_LE(int(reduced.size()), kMaxHullVertices);
  EXPECT_EQ(reduced.size(), full.size());
  for (const Eigen::Vector3d& p : reduced) EXPECT_TRUE(contains(hull, p));
  // Both reductions lie inside the sphere and keep most of its volume.
  Mesh a, b;
  a.vertices = reduced;
  b.vertices = full;
  for (Mesh* m : {&a, &b})
    for (int i = 0; i + 2 < int(m->vertices.size()); ++i)
      m->triangles.emplace_back(0, i + 1, i + 2);
  const double exact = convex_hull_volume(sphere).volume_m3;
  EXPECT_GT(convex_hull_volume(a).volume_m3, 0.9 * exact);
  EXPECT_GT(convex_hull_volume(b).volume_m3, 0.9 * exact);
  EXPECT_LE(convex_hull_volume(a).volume_m3, exact * (1 + 1e-12));
}

TEST(ReducedConvexHull, ReturnsFewPointsAsGiven) {
  const std::vector<Eigen::Vector3d> few = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0),
                                            Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1)};
  EXPECT_EQ(reduced_convex_hull(few, kMaxHullVertices), few);
}

/// A thin-walled object's parts may overlap at their seams, but not fill it: the sum of their
/// hull volumes against the mesh's (1.01 for the shipped mug; 4.2 when a grid clustering of
/// the HACD input merged its inner and outer wall and the parts filled the cup).
constexpr double kMaxPartVolumeRatio = 1.25;

TEST(ConvexDecomposition, ThinWalledCupKeepsItsCavity) {
  const Mesh mug = make_mug_object();
  DecompositionParams params;
  ASSERT_GT(static_cast<int>(mug.triangles.size()), params.max_input_triangles);  // simplified
  const ConvexDecomposition d = convex_decomposition(mug, params);
  ASSERT_GT(d.parts.size(), 1u);
  double parts_m3 = 0.0;
  for (const auto& part : d.parts) {
    parts_m3 += convex_hull_volume(part).volume_m3;
  }
  const auto solid = closed_mesh_volume(mug);
  ASSERT_TRUE(solid.has_value());
  EXPECT_LT(parts_m3, kMaxPartVolumeRatio * solid->volume_m3);
  EXPECT_GT(parts_m3, solid->volume_m3 / kMaxPartVolumeRatio);
  // Inside the cup (axis z, inner radius 36 mm, floor at 6 mm, rim at 95 mm): no part.
  const MugObjectParams mug_params;
  const double r_in = 0.5 * mug_params.outer_diameter_m - mug_params.wall_m;
  for (const double z : {0.02, 0.04, 0.06, 0.08})
    for (const double r : {0.0, 0.6 * r_in})
      for (const double a : {0.0, 2.0, 4.0}) {
        const Eigen::Vector3d p(r * std::cos(a), r * std::sin(a), z);
        for (size_t i = 0; i < d.parts.size(); ++i)
          EXPECT_TRUE(outside_hull(d.parts[i], p)) << "part " << i << " holds " << p.transpose();
      }
  // The floor's centre is in the material: some part holds it (the test above can fail).
  const Eigen::Vector3d floor(0.0, 0.0, 0.5 * mug_params.bottom_m);
  EXPECT_TRUE(std::any_of(d.parts.begin(), d.parts.end(),
                          [&](const auto& part) { return !outside_hull(part, floor); }));
}

}  // namespace
}  // namespace cordgrasp
