// Contact-based measures of a candidate grasp (reported per grasp in plan.json).
#include <gtest/gtest.h>

#include <cmath>

#include "cordgrasp/collision/bullet_hand_collider.h"
#include "cordgrasp/core/candidate_measures.h"
#include "cordgrasp/core/plan_cord_grasps.h"
#include "cordgrasp/core/shapes.h"
#include "test_hands.h"

namespace cordgrasp {
namespace {

// Links 1, 2, 3 are three one-link fingers; link 0 is the palm.
HandSetup three_finger_setup() {
  HandSetup s;
  s.num_links = 4;
  s.actor_links = {{1}, {2}, {3}};
  s.static_links = {0};
  return s;
}

Contact contact(int link, const Eigen::Vector3d& p, const Eigen::Vector3d& n) {
  Contact c;
  c.link = link;
  c.p_O = p;
  c.n_O = n.normalized();
  return c;
}

TEST(CandidateMeasures, TwoOpposedFingersAreBalancedAndCentred) {
  const std::vector<Contact> contacts = {contact(1, {0.02, 0, 0}, {1, 0, 0}),
                                         contact(2, {-0.02, 0, 0}, {-1, 0, 0})};
  const CandidateMeasures m =
      candidate_measures(contacts, three_finger_setup(), Eigen::Vector3d::Zero(), 0.05);
  EXPECT_EQ(m.fingers_in_contact, 2);
  EXPECT_FALSE(m.palm_contact);
  EXPECT_NEAR(m.com_offset, 0.0, 1e-12);
  EXPECT_NEAR(m.push_imbalance, 0.0, 1e-12);
}

TEST(CandidateMeasures, OneFingerAgainstTwoLeavesANetPush) {
  // Finger 1 pushes −x, fingers 2 and 3 push +x: net one finger's push over three fingers.
  const std::vector<Contact> contacts = {contact(1, {0.02, 0.0, 0}, {1, 0, 0}),
                                         contact(2, {-0.02, 0.01, 0}, {-1, 0, 0}),
                                         contact(3, {-0.02, -0.01, 0}, {-1, 0, 0})};
  const CandidateMeasures m =
      candidate_measures(contacts, three_finger_setup(), {0.0, 0.0, 0.03}, 0.05);
  EXPECT_EQ(m.fingers_in_contact, 3);
  EXPECT_NEAR(m.push_imbalance, 1.0 / 3.0, 1e-12);
  // Contact mean (−0.02/3, 0, 0), 3 cm below the centre of mass.
  EXPECT_NEAR(m.com_offset, std::hypot(0.02 / 3.0, 0.03) / 0.05, 1e-12);
}

TEST(CandidateMeasures, ThePalmTakesWhatPressesTheObjectOntoIt) {
  // Two fingers push −z (object onto the palm below it, whose normal points −z from the object);
  // two contacts on one finger count as one finger pushing along their mean normal.
  const std::vector<Contact> contacts = {
      contact(1, {0.01, 0, 0.01}, {0, 0, 1}), contact(2, {-0.01, 0, 0.01}, {1, 0, 1}),
      contact(2, {-0.01, 0, 0.01}, {-1, 0, 1}), contact(0, {0, 0, -0.01}, {0, 0, -1})};
  const CandidateMeasures m =
      candidate_measures(contacts, three_finger_setup(), Eigen::Vector3d::Zero(), 0.05);
  EXPECT_EQ(m.fingers_in_contact, 2);
  EXPECT_TRUE(m.palm_contact);
  EXPECT_NEAR(m.push_imbalance, 0.0, 1e-12);
  // Without the palm contact the same fingers push the object away: imbalance 1.
  const std::vector<Contact> no_palm(contacts.begin(), contacts.begin() + 3);
  EXPECT_NEAR(candidate_measures(no_palm, three_finger_setup(), Eigen::Vector3d::Zero(), 0.05)
                  .push_imbalance,
              1.0, 1e-12);
}

GraspRegion cylinder_region(double r, double d) {
  GraspRegion g;
  g.p1 = {d, 0.0, 0.0};
  const double x = r * r / d, y = r * std::sqrt(1.0 - r * r / (d * d));
  g.p_l = {x, y, 0.0};
  g.p_r = {x, -y, 0.0};
  g.p_m = 0.5 * (g.p_l + g.p_r);
  g.normal = Eigen::Vector3d::UnitZ();
  g.chi_m2 = 1e-4;
  return g;
}

TEST(CandidateMeasures, PlannedGraspsCarryThem) {
  const Mesh cylinder = make_cylinder_mesh(0.015, 0.3);
  const HandModel hand = test::make_three_finger_hand();
  auto collider = make_bullet_hand_collider(hand, cylinder);
  const std::vector<GraspRegion> regions = {cylinder_region(0.015, 0.15)};
  const PlanResult plan =
      plan_cord_grasps_from_regions(cylinder, hand, *collider, regions, PlanParams{});
  ASSERT_EQ(plan.grasps.size(), 1u);
  const Grasp& g = plan.grasps[0];
  EXPECT_GE(g.measures.fingers_in_contact, 2);
  EXPECT_LT(g.measures.com_offset, 0.1);  // on the cylinder's middle cross-section
}

}  // namespace
}  // namespace cordgrasp
