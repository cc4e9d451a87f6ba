#include "cordgrasp/core/winding_number.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>

#include "cordgrasp/core/shape_builders.h"
#include "cordgrasp/core/shapes.h"

namespace cordgrasp {
namespace {

/// Far-field dipoles against the exact sum, at points no closer to the surface than 1 mm (the
/// inside test thresholds at 0.5).
constexpr double kApproximationTol = 0.03;

WindingNumberTree tree_of(const Mesh& mesh) {
  return build_winding_number_tree(std::make_shared<const MeshBvh>(build_mesh_bvh(mesh)));
}

/// Exact winding number: every triangle's solid angle.
double exact_winding_number(const Mesh& mesh, const Eigen::Vector3d& p) {
  double omega = 0.0;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Eigen::Vector3d a = mesh.vertices[static_cast<size_t>(t[0])] - p;
    const Eigen::Vector3d b = mesh.vertices[static_cast<size_t>(t[1])] - p;
    const Eigen::Vector3d c = mesh.vertices[static_cast<size_t>(t[2])] - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    omega += 2.0 * std::atan2(a.dot(b.cross(c)),
                              la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb);
  }
  return omega / (4.0 * M_PI);
}

TEST(WindingNumber, OneInsideATorusTubeZeroInItsHoleAndOutside) {
  const Mesh torus = make_torus_mesh(0.05, 0.015, 48, 24);
  const WindingNumberTree tree = tree_of(torus);
  EXPECT_NEAR(winding_number(tree, {0.05, 0.0, 0.0}), 1.0, kApproximationTol);
  EXPECT_NEAR(winding_number(tree, {0.0, -0.06, 0.005}), 1.0, kApproximationTol);
  EXPECT_NEAR(winding_number(tree, {0.0, 0.0, 0.0}), 0.0, kApproximationTol);  // the hole
  EXPECT_NEAR(winding_number(tree, {0.0, 0.0, 0.03}), 0.0, kApproximationTol);
  EXPECT_NEAR(winding_number(tree, {0.2, 0.1, -0.1}), 0.0, kApproximationTol);
}

TEST(WindingNumber, MatchesTheExactSumAwayFromTheSurface) {
  const Mesh mesh = make_swept_tube_mesh(
      {{-0.05, 0.0, 0.0}, {0.0, 0.03, 0.01}, {0.04, 0.0, 0.03}, {0.05, -0.04, 0.0}}, 0.012);
  const WindingNumberTree tree = tree_of(mesh);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-0.06, 0.06);
  int compared = 0, inside = 0;
  for (int i = 0; i < 1000; ++i) {
    const Eigen::Vector3d p(u(rng), u(rng), u(rng));
    double nearest = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3d& v : mesh.vertices) nearest = std::min(nearest, (v - p).norm());
    if (nearest < 1e-3) continue;
    const double exact = exact_winding_number(mesh, p);
    EXPECT_NEAR(winding_number(tree, p), exact, kApproximationTol) << p.transpose();
    ++compared;
    inside += exact > 0.5;
  }
  EXPECT_GT(compared, 800);
  EXPECT_GT(inside, 10);  // the comparison saw the inside too
}

TEST(WindingNumber, CountsOverlapsTwiceAndReversedWindingNegative) {
  Mesh two = make_box_mesh({0.04, 0.04, 0.04});
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() = Eigen::Vector3d(0.03, 0.0, 0.0);
  append_mesh(two, make_box_mesh({0.04, 0.04, 0.04}), X);
  const WindingNumberTree tree = tree_of(two);
  EXPECT_NEAR(winding_number(tree, {0.015, 0.0, 0.0}), 2.0, kApproximationTol);
  EXPECT_NEAR(winding_number(tree, {-0.015, 0.0, 0.0}), 1.0, kApproximationTol);
  EXPECT_NEAR(winding_number(tree, {0.1, 0.0, 0.0}), 0.0, kApproximationTol);

  Mesh reversed = make_box_mesh({0.04, 0.04, 0.04});
  for (Eigen::Vector3i& t : reversed.triangles) std::swap(t[1], t[2]);
  EXPECT_NEAR(winding_number(tree_of(reversed), Eigen::Vector3d::Zero()), -1.0, kApproximationTol);
}

}  // namespace
}  // namespace cordgrasp
