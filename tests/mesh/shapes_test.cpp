#include <gtest/gtest.h>

#include <cmath>

#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/core/shapes.h"

namespace cordgrasp {
namespace {

constexpr double kTol = 1e-12;

/// Signed volume by the divergence theorem: positive iff triangles face outward.
double signed_volume(const Mesh& m) {
  double v = 0;
  for (const auto& t : m.triangles)
    v += m.vertices[t[0]].dot(m.vertices[t[1]].cross(m.vertices[t[2]])) / 6.0;
  return v;
}

TEST(Shapes, BoxHasOutwardFacesAndExactVolume) {
  const Mesh box = make_box_mesh({0.1, 0.2, 0.3});
  EXPECT_NEAR(signed_volume(box), 0.006, kTol);
  EXPECT_TRUE(mesh_bounds(box).size().isApprox(Eigen::Vector3d(0.1, 0.2, 0.3)));
}

TEST(Shapes, CylinderSphereTorusFaceOutward) {
  EXPECT_GT(signed_volume(make_cylinder_mesh(0.02, 0.2)), 0.0);
  EXPECT_GT(signed_volume(make_sphere_mesh(0.05)), 0.0);
  EXPECT_GT(signed_volume(make_torus_mesh(0.05, 0.01)), 0.0);
  // Inscribed polygon prism: V = (n/2) r² sin(2π/n) L.
  const int n = 48;
  EXPECT_NEAR(signed_volume(make_cylinder_mesh(0.02, 0.2, n)),
              0.5 * n * 0.0004 * std::sin(2 * M_PI / n) * 0.2, 1e-15);
}

TEST(Shapes, SphereVerticesLieOnTheSphereAndMeanIsCentre) {
  const Mesh s = make_sphere_mesh(0.04);
  const Eigen::Vector3d c = vertex_mean(s);
  EXPECT_LT(c.norm(), kTol);
  EXPECT_NEAR(bounding_radius(s, c), 0.04, kTol);
  for (const auto& v : s.vertices) EXPECT_NEAR(v.norm(), 0.04, kTol);
}

TEST(Shapes, AppendMeshTransformsAndReindexes) {
  Mesh a = make_box_mesh({1, 1, 1});
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() = Eigen::Vector3d(5, 0, 0);
  append_mesh(a, make_box_mesh({1, 1, 1}), X);
  EXPECT_EQ(a.vertices.size(), 16u);
  EXPECT_EQ(a.triangles.size(), 24u);
  EXPECT_NEAR(mesh_bounds(a).max.x(), 5.5, kTol);
  EXPECT_NEAR(signed_volume(a), 2.0, kTol);
}

}  // namespace
}  // namespace cordgrasp
