// The fingertips' meeting point of hand drafting (core/src/fingertip_meeting_point.h) against
// the closed form for two straight one-joint digits curling towards each other.
#include "fingertip_meeting_point.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "urdf_import.h"

namespace cordgrasp::hand_draft {
namespace {

namespace fs = std::filesystem;

constexpr double kHalfGap_m = 0.03;   // each digit's root from the mid-plane x = 0
constexpr double kLength_m = 0.06;    // root to fingertip
constexpr int kSamples = 40;          // MeetingPointParams::samples
constexpr double kSweep_rad = M_PI / 2;

/// Two digits standing up (+z) from a palm at x = -/+ kHalfGap_m, each turning about +/-y so
/// that its positive motion (limits [0, pi/2]) curls its tip towards x = 0.
HandModel two_opposed_digits() {
  const fs::path path = fs::temp_directory_path() / "cordgrasp_meeting_point_test.urdf";
  std::ofstream(path) << R"(<?xml version="1.0"?>
<robot name="two_digits">
  <link name="palm"><collision><geometry><box size="0.1 0.03 0.02"/></geometry></collision>
  </link>
  <link name="left"/>
  <link name="right"/>
  <joint name="left_flex" type="revolute"><parent link="palm"/><child link="left"/>
    <origin xyz="-0.03 0 0"/><axis xyz="0 1 0"/>
    <limit lower="0" upper="1.5707963267949" effort="1" velocity="1"/></joint>
  <joint name="right_flex" type="revolute"><parent link="palm"/><child link="right"/>
    <origin xyz="0.03 0 0"/><axis xyz="0 -1 0"/>
    <limit lower="0" upper="1.5707963267949" effort="1" velocity="1"/></joint>
</robot>
)";
  return hand_load::import_urdf(path.string());
}

int joint_named(const HandModel& hand, const std::string& name) {
  for (size_t j = 0; j < hand.joints.size(); ++j)
    if (hand.joints[j].name == name) return static_cast<int>(j);
  return -1;
}

TEST(FingertipMeetingPoint, TwoCurlingDigitsMeetAboveTheMidPlaneWhereTheClosedFormSays) {
  const HandModel hand = two_opposed_digits();
  std::vector<ClosingDigit> digits(2);
  const char* names[] = {"left_flex", "right_flex"};
  for (int i = 0; i < 2; ++i) {
    const int j = joint_named(hand, names[i]);
    ASSERT_GE(j, 0);
    digits[i].tip_link = hand.joints[j].child_link;
    digits[i].p_tip_L = Eigen::Vector3d(0, 0, kLength_m);
    digits[i].closed_q = {{j, kSweep_rad}};
  }
  const MeetingPoint meet =
      fingertip_meeting_point(hand, Eigen::VectorXd::Zero(hand.joints.size()), digits);
  ASSERT_TRUE(meet.found);
  // Tips at (-/+(d - L sin t), 0, L cos t): they touch at sin t = d / L.
  const double t = std::asin(kHalfGap_m / kLength_m);
  const double step_rad = kSweep_rad / (kSamples - 1);
  const double tol_m = kLength_m * step_rad;  // one sample of the sweep
  EXPECT_NEAR(meet.p_W.x(), 0.0, 1e-12);
  EXPECT_NEAR(meet.p_W.y(), 0.0, 1e-12);
  EXPECT_NEAR(meet.p_W.z(), kLength_m * std::cos(t), tol_m);
  EXPECT_NEAR(meet.closure, t / kSweep_rad, 1.0 / (kSamples - 1));
  EXPECT_NEAR(meet.spread_open_m, 2 * kHalfGap_m, 1e-12);
  EXPECT_LT(meet.spread_m, 2 * tol_m);

  // Each starts closing straight towards the other: +x for the left digit, -x for the right,
  // at L times the sweep's turn per unit of closure.
  ASSERT_EQ(meet.start_motion_W.size(), 2u);
  const double speed_m = kLength_m * kSweep_rad;
  EXPECT_NEAR(meet.start_motion_W[0].x(), speed_m, 0.01 * speed_m);
  EXPECT_NEAR(meet.start_motion_W[1].x(), -speed_m, 0.01 * speed_m);
  EXPECT_LT(std::abs(meet.start_motion_W[0].z()), 0.05 * speed_m);

  // The digits close towards each other along x, the palm (x = 0) between their roots.
  std::vector<Eigen::Vector3d> roots{{-kHalfGap_m, 0, 0}, {kHalfGap_m, 0, 0}};
  const std::vector<Eigen::Vector3d>& motion = meet.start_motion_W;
  const Eigen::Vector3d axis = main_closing_axis(motion);
  EXPECT_NEAR(std::abs(axis.x()), 1.0, 0.05) << axis.transpose();
  const Opposition o = opposition_across(Eigen::Vector3d::UnitX(), roots, motion,
                                         Eigen::Vector3d::Zero(), 0.5);
  EXPECT_EQ(o.along, std::vector<int>{0});
  EXPECT_EQ(o.against, std::vector<int>{1});
  EXPECT_NEAR(o.roots_apart_cosine, 1.0, 1e-12);
  EXPECT_NEAR(o.palm_between, 0.5, 1e-12);
  // Along z (the palm normal) nobody closes either way: no opposition.
  const Opposition none = opposition_across(Eigen::Vector3d::UnitZ(), roots, motion,
                                            Eigen::Vector3d::Zero(), 0.5);
  EXPECT_TRUE(none.along.empty() && none.against.empty());
}

TEST(FingertipMeetingPoint, DigitsThatDoNotCloseHaveNoMeetingPoint) {
  const HandModel hand = two_opposed_digits();
  std::vector<ClosingDigit> digits(2);
  for (int i = 0; i < 2; ++i) {
    digits[i].tip_link = hand.joints[i].child_link;
    digits[i].p_tip_L = Eigen::Vector3d(0, 0, kLength_m);
  }
  EXPECT_FALSE(
      fingertip_meeting_point(hand, Eigen::VectorXd::Zero(hand.joints.size()), digits).found);
}

TEST(FingertipMeetingPoint, RootsSpreadOverAFaceGiveItsNormalAndARowGivesNone) {
  // Three roots on a tilted face: two on one side, one across (an opposed three-digit hand).
  const Eigen::Vector3d n = Eigen::Vector3d(1, 2, 3).normalized();
  const Eigen::Vector3d u = n.unitOrthogonal(), v = n.cross(u);
  const std::vector<Eigen::Vector3d> face = {0.03 * u + 0.02 * v, 0.03 * u - 0.02 * v, -0.03 * u};
  const RootsPlane plane = roots_plane(face);
  ASSERT_TRUE(plane.found);
  EXPECT_NEAR(std::abs(plane.normal_W.dot(n)), 1.0, 1e-9);
  // Collinear roots (fingers in a row) and two roots span no plane.
  EXPECT_FALSE(roots_plane({-0.02 * u, 0.001 * v, 0.02 * u}).found);
  EXPECT_FALSE(roots_plane({-0.02 * u, 0.02 * u}).found);
  // Roots off the face by as much as across it (a thumb standing out) are not a face.
  EXPECT_FALSE(roots_plane({0.03 * u, -0.03 * u, 0.03 * v, 0.03 * n}).found);
}

TEST(FingertipMeetingPoint, TheOneDigitPointingOutOfARowOfParallelFingersIsFound) {
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d tilted = Eigen::Vector3d(1, 0, 1).normalized();  // 45° off the row
  const OddDirection odd = odd_direction_out_of_row({up, up, tilted, up}, 0.95, 0.2);
  EXPECT_EQ(odd.index, 2);
  EXPECT_NEAR(odd.cosine, std::sqrt(0.5), 1e-12);
  // All parallel (a Barrett-like hand at rest), or two odd ones: none.
  EXPECT_EQ(odd_direction_out_of_row({up, up, up}, 0.95, 0.2).index, -1);
  EXPECT_EQ(odd_direction_out_of_row({up, tilted, Eigen::Vector3d::UnitX()}, 0.95, 0.2).index, -1);
  // Off the row by less than the margin: not out of it.
  const Eigen::Vector3d near = Eigen::Vector3d(0.3, 0, 1).normalized();  // cosine 0.958
  EXPECT_EQ(odd_direction_out_of_row({up, up, near}, 0.95, 0.2).index, -1);
}

}  // namespace
}  // namespace cordgrasp::hand_draft
