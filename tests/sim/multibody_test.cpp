// The hand as a btMultiBody: Bullet's forward kinematics against the planner's.
#include <gtest/gtest.h>

#include <random>

#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/kinematics.h"
#include "cordgrasp/sim/validate_grasp.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

constexpr double kPoseTol_m = 1e-9;
constexpr double kRotTol_rad = 1e-9;
constexpr int kRandomConfigurations = 20;

/// Random joint vector within limits (couplings applied) and random root pose.
void random_state(const HandModel& hand, std::mt19937_64& rng, Eigen::VectorXd& q,
                  Eigen::Isometry3d& X_WB) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  q = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(hand.joints.size()));
  for (size_t j = 0; j < hand.joints.size(); ++j) {
    const Joint& joint = hand.joints[j];
    if (!joint.is_moving()) continue;
    const double lo = std::isfinite(joint.lower) ? joint.lower : -M_PI;
    const double hi = std::isfinite(joint.upper) ? joint.upper : M_PI;
    q[static_cast<Eigen::Index>(j)] = lo + (hi - lo) * u(rng);
  }
  q = apply_couplings(hand, q);
  X_WB = Eigen::Isometry3d::Identity();
  X_WB.linear() = Eigen::Quaterniond(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5)
                      .normalized()
                      .toRotationMatrix();
  X_WB.translation() = Eigen::Vector3d(u(rng), u(rng), u(rng)) - Eigen::Vector3d::Constant(0.5);
}

void expect_fk_agrees(const HandModel& hand) {
  std::mt19937_64 rng(7);
  for (int k = 0; k < kRandomConfigurations; ++k) {
    Eigen::VectorXd q;
    Eigen::Isometry3d X_WB;
    random_state(hand, rng, q, X_WB);
    const auto expected = link_poses(hand, q, X_WB);
    // Every other configuration locks every other moving joint (merged as fixed at its value).
    std::vector<bool> locked;
    if (k % 2 == 1)
      for (size_t j = 0; j < hand.joints.size(); ++j)
        locked.push_back(j % 2 == 0 && !hand.joints[j].mimic);
    const auto bullet = multibody_link_poses(hand, q, X_WB, locked);
    ASSERT_EQ(bullet.size(), expected.size());
    for (size_t l = 0; l < expected.size(); ++l) {
      EXPECT_LT((bullet[l].translation() - expected[l].translation()).norm(), kPoseTol_m)
          << hand.name << " link " << hand.links[l].name << " configuration " << k;
      EXPECT_LT(Eigen::AngleAxisd(bullet[l].linear().transpose() * expected[l].linear()).angle(),
                kRotTol_rad)
          << hand.name << " link " << hand.links[l].name << " configuration " << k;
    }
  }
}

TEST(HandMultiBody, BulletLinkPosesMatchForwardKinematicsForShippedHands) {
  expect_fk_agrees(load_hand("cordgrasp_sah"));
  expect_fk_agrees(load_hand("parallel_gripper"));
}

TEST(HandMultiBodyDataset, BulletLinkPosesMatchForwardKinematicsForSharedHands) {
  CORDGRASP_REQUIRE_SHARED_DATA();
  for (const char* name : {"schunk_sah", "panda_hand", "icub_right_hand", "armar3_right_hand",
                           "allegro_right", "barrett_bh282"})
    expect_fk_agrees(load_hand(name));
}

}  // namespace
}  // namespace cordgrasp
