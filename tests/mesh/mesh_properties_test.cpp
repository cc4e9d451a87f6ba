#include <gtest/gtest.h>

#include <cmath>

#include "cordgrasp/core/mesh_properties.h"

namespace cordgrasp {
namespace {

constexpr double kTol = 1e-12;

Mesh make_tetra() {
  Mesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return m;
}

TEST(MeshProperties, BoundsAndVertexMeanOfTetrahedron) {
  const Mesh m = make_tetra();
  const Aabb box = mesh_bounds(m);
  EXPECT_TRUE(box.min.isApprox(Eigen::Vector3d::Zero()));
  EXPECT_TRUE(box.max.isApprox(Eigen::Vector3d::Ones()));
  const Eigen::Vector3d c = vertex_mean(m);
  EXPECT_NEAR(c.x(), 0.25, kTol);
  EXPECT_NEAR(bounding_radius(m, c), std::sqrt(0.75 * 0.75 + 2 * 0.0625), kTol);
}

TEST(MeshProperties, PrincipalAxisOfThinRectangleIsItsLongSide) {
  Mesh m;
  m.vertices = {{-2, -0.1, 0}, {2, -0.1, 0}, {2, 0.1, 0}, {-2, 0.1, 0}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  const PrincipalAxes pa = principal_axes(m);
  EXPECT_NEAR(std::abs(pa.axes.col(0).x()), 1.0, 1e-12);
  EXPECT_NEAR(pa.area_m2, 0.8, kTol);
  // Uniform rectangle of length 4: variance along x is 4²/12.
  EXPECT_NEAR(pa.variances[0], 16.0 / 12.0, 1e-12);
  EXPECT_GE(pa.variances[0], pa.variances[1]);
  EXPECT_GE(pa.variances[1], pa.variances[2]);
}

}  // namespace
}  // namespace cordgrasp
