#include "cordgrasp/core/grasp_perturbation.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cordgrasp {
namespace {

constexpr double kTol = 1e-12;

Grasp some_grasp() {
  Grasp g;
  g.X_OG = Eigen::Translation3d(0.01, -0.02, 0.05) * Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized());
  g.X_OB = g.X_OG * Eigen::Translation3d(0.0, 0.01, -0.09);
  g.q = Eigen::VectorXd::Constant(3, 0.4);
  g.q_preshape = Eigen::VectorXd::Zero(3);
  return g;
}

TEST(PerturbedGrasp, MovesTheGcpByTheOffsetAndTurnsTheHandByTheAngle) {
  const Grasp g = some_grasp();
  PerturbationParams params;
  params.offset_m = 2e-4;
  params.turn_rad = 3e-3;
  const Grasp p = perturbed_grasp(g, params, 7);
  EXPECT_NEAR((p.X_OG.translation() - g.X_OG.translation()).norm(), params.offset_m, kTol);
  const Eigen::AngleAxisd turn(p.X_OG.linear() * g.X_OG.linear().transpose());
  EXPECT_NEAR(turn.angle(), params.turn_rad, kTol);
  // The hand moves rigidly: root relative to the GCP and the joints are unchanged.
  EXPECT_TRUE((p.X_OG.inverse() * p.X_OB).isApprox(g.X_OG.inverse() * g.X_OB, kTol));
  EXPECT_EQ(p.q, g.q);
  EXPECT_EQ(p.q_preshape, g.q_preshape);
}

TEST(PerturbedGrasp, SameSeedSameGraspOtherSeedOtherDirection) {
  const Grasp g = some_grasp();
  const Grasp a = perturbed_grasp(g, {}, 1);
  const Grasp b = perturbed_grasp(g, {}, 1);
  const Grasp c = perturbed_grasp(g, {}, 2);
  EXPECT_TRUE(a.X_OB.isApprox(b.X_OB, 0.0));
  EXPECT_FALSE(a.X_OG.translation().isApprox(c.X_OG.translation(), 1e-9));
}

TEST(PerturbedGrasp, ZeroPerturbationLeavesTheGraspAsItIs) {
  const Grasp g = some_grasp();
  const Grasp p = perturbed_grasp(g, {0.0, 0.0}, 3);
  EXPECT_TRUE(p.X_OB.isApprox(g.X_OB, kTol));
  EXPECT_TRUE(p.X_OG.isApprox(g.X_OG, kTol));
}

}  // namespace
}  // namespace cordgrasp
