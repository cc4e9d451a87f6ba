// Contact-based measures of a candidate grasp (reported per grasp in plan.json).
#include <gtest/gtest.h>

#include <cmath>

#include "cordgrasp/core/candidate_measures.h"

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

}  // namespace
}  // namespace cordgrasp
