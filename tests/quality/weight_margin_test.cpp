// Weight margin (core weight_margin.h): the largest multiple of the object's weight that the
// planned contacts carry within the joints' effort limits, against closed-form cases.
#include "cordgrasp/core/weight_margin.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "test_hands.h"

namespace cordgrasp {
namespace {

// An 8-edge pyramid inscribed in the friction cone carries between cos(π/8) and 1 of the
// cone's tangential force, depending on the direction.
constexpr double kPyramidLow = 0.92388;  // cos(π/8)
constexpr double kSolverTol = 1e-7;

// The test gripper's jaws (prismatic, closing along ±x) pressing a box whose centre of mass is
// the origin, at x = ∓half_width_m on the jaw axis.
Grasp pinch(const HandModel& hand, double half_width_m) {
  Grasp g;
  g.q = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(hand.joints.size()));
  g.q[find_joint(hand, "left_joint")] = 0.055 - half_width_m;
  g.q[find_joint(hand, "right_joint")] = 0.055 - half_width_m;
  g.X_OB.translation() = Eigen::Vector3d(0, 0, -0.04);  // jaws' middle at the COM height
  Contact left, right;
  left.link = find_link(hand, "left");
  left.p_O = Eigen::Vector3d(-half_width_m, 0, 0);
  left.n_O = -Eigen::Vector3d::UnitX();  // out of the object, toward the jaw
  right.link = find_link(hand, "right");
  right.p_O = Eigen::Vector3d(half_width_m, 0, 0);
  right.n_O = Eigen::Vector3d::UnitX();
  g.contacts = {left, right};
  return g;
}

ContactModel point_contacts(double mu) {
  ContactModel c;
  c.mu = mu;
  c.soft_finger_radius_m = 0.0;
  return c;
}

StaticLoad weight_down(double weight_N, const Eigen::Vector3d& com_O_m = Eigen::Vector3d::Zero()) {
  StaticLoad load;
  load.com_O_m = com_O_m;
  load.weight_O_N = Eigen::Vector3d(0, 0, -weight_N);
  return load;
}

TEST(WeightMargin, PinchCarriesTwiceMuTimesTheJawForce) {
  const HandModel h = test::make_parallel_gripper();
  const Grasp g = pinch(h, 0.03);
  testing::internal::CaptureStdout();  // the solver prints nothing
  for (const double mu : {0.3, 0.5, 1.0})
    for (const double force_N : {2.0, 10.0, 40.0}) {
      const Eigen::VectorXd efforts = Eigen::VectorXd::Constant(2, force_N);
      const double weight_N = 5.0;
      const double analytic = 2.0 * mu * force_N / weight_N;  // holds iff 2μF ≥ m·g
      const double margin = weight_margin(h, g, point_contacts(mu), weight_down(weight_N), efforts);
      EXPECT_GE(margin, kPyramidLow * analytic - kSolverTol) << "mu " << mu << " F " << force_N;
      EXPECT_LE(margin, analytic + kSolverTol) << "mu " << mu << " F " << force_N;
    }
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
}

TEST(WeightMarginPinch, IsLinearInTheEffortLimits) {
  const HandModel h = test::make_parallel_gripper();
  const Grasp g = pinch(h, 0.03);
  const ContactModel c = point_contacts(0.5);
  const double one = weight_margin(h, g, c, weight_down(4.0), Eigen::VectorXd::Constant(2, 3.0));
  const double two = weight_margin(h, g, c, weight_down(4.0), Eigen::VectorXd::Constant(2, 6.0));
  ASSERT_GT(one, 0.0);
  EXPECT_NEAR(two, 2.0 * one, 1e-6 * one);
  // The weaker jaw sets the squeeze: what one jaw pushes, the other must push back.
  Eigen::VectorXd uneven(2);
  uneven << 3.0, 60.0;
  EXPECT_NEAR(weight_margin(h, g, c, weight_down(4.0), uneven), one, 1e-6 * one);
}

TEST(WeightMarginPinch, TorqueAboutThePinchAxisNeedsSoftFingers) {
  // The centre of mass 4 cm off the jaw axis (along y): the weight turns the object about the
  // axis through both contacts. Point contacts cannot resist that; soft fingers resist up to
  // μ·ρ·F each (torsional friction of a patch of radius ρ).
  const HandModel h = test::make_parallel_gripper();
  const Grasp g = pinch(h, 0.03);
  const double force_N = 20.0, weight_N = 2.0, offset_m = 0.04, mu = 0.5, rho_m = 0.005;
  const StaticLoad load = weight_down(weight_N, Eigen::Vector3d(0, offset_m, 0));
  const Eigen::VectorXd efforts = Eigen::VectorXd::Constant(2, force_N);
  EXPECT_NEAR(weight_margin(h, g, point_contacts(mu), load, efforts), 0.0, kSolverTol);
  ContactModel soft = point_contacts(mu);
  soft.soft_finger_radius_m = rho_m;
  const double torsion = 2.0 * mu * rho_m * force_N / (weight_N * offset_m);
  const double lift = 2.0 * mu * force_N / weight_N;
  ASSERT_LT(torsion, kPyramidLow * lift);  // the torsion binds
  EXPECT_NEAR(weight_margin(h, g, soft, load, efforts), torsion, 1e-6 * torsion);
}

TEST(WeightMargin, PalmUnderTheObjectCarriesAnyWeight) {
  // Contacts on the root link are not limited by any joint: an object resting on the palm.
  const HandModel h = test::make_parallel_gripper();
  Grasp g = pinch(h, 0.03);
  Contact palm;
  palm.link = h.root_link;
  palm.p_O = Eigen::Vector3d(0, 0, -0.02);
  palm.n_O = -Eigen::Vector3d::UnitZ();
  g.contacts.push_back(palm);
  const double cap = 50.0;
  EXPECT_NEAR(weight_margin(h, g, point_contacts(0.5), weight_down(100.0),
                            Eigen::VectorXd::Constant(2, 1.0), cap),
              cap, kSolverTol);
}

TEST(WeightMargin, UnboundedJointsAndEmptyGrasps) {
  const HandModel h = test::make_parallel_gripper();
  const Grasp g = pinch(h, 0.03);
  const ContactModel c = point_contacts(0.5);
  const double cap = 100.0;
  // Efforts ≤ 0 or infinite bound nothing (locked joints): the pinch carries any weight.
  for (const double e : {0.0, -1.0, std::numeric_limits<double>::infinity()})
    EXPECT_NEAR(weight_margin(h, g, c, weight_down(50.0), Eigen::VectorXd::Constant(2, e), cap),
                cap, kSolverTol)
        << e;
  Grasp none = g;
  none.contacts.clear();
  EXPECT_EQ(weight_margin(h, none, c, weight_down(1.0), Eigen::VectorXd::Constant(2, 1.0)), 0.0);
  EXPECT_THROW(weight_margin(h, g, c, weight_down(1.0), Eigen::VectorXd::Constant(3, 1.0)),
               std::invalid_argument);
}

}  // namespace
}  // namespace cordgrasp
