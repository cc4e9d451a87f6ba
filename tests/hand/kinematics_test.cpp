// apply_couplings, clamp_to_limits, link_poses, root_pose_for_gcp, contact_force_torques,
// contact_levers
// on the shipped and test hands.
#include "cordgrasp/core/kinematics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "cordgrasp/core/hand_io.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

constexpr double kTol = 1e-12;
constexpr double kPosTol_m = 1e-9;

TEST(ApplyCouplings, SetsEveryMimicJointFromItsMaster) {
  const HandModel h = load_hand("cordgrasp_sah");
  Eigen::VectorXd q = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(h.joints.size()));
  q[find_joint(h, "index_middle")] = 0.8;
  q[find_joint(h, "index_distal")] = -3.0;  // overwritten
  q[find_joint(h, "thumb_middle")] = 0.3;
  const Eigen::VectorXd out = apply_couplings(h, q);
  EXPECT_DOUBLE_EQ(out[find_joint(h, "index_distal")], 0.8);
  EXPECT_DOUBLE_EQ(out[find_joint(h, "thumb_distal")], 0.3);
  EXPECT_DOUBLE_EQ(out[find_joint(h, "ring_distal")], 0.0);
  for (size_t j = 0; j < h.joints.size(); ++j) {
    if (!h.joints[j].mimic) {
      EXPECT_EQ(out[j], q[j]) << h.joints[j].name;
    }
  }
}

TEST(ApplyCouplings, UsesMultiplierAndOffset) {
  const HandModel h = load_hand(test::test_data("hands/features/features.yaml"));
  Eigen::VectorXd q = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(h.joints.size()));
  q[find_joint(h, "slide")] = 0.01;
  EXPECT_NEAR(apply_couplings(h, q)[find_joint(h, "slide mirror")], 0.011, kTol);
}

TEST(ClampToLimits, ClampsRevoluteAndPrismaticLeavesContinuousAndFixed) {
  const HandModel h = load_hand(test::test_data("hands/features/features.yaml"));
  Eigen::VectorXd q = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(h.joints.size()));
  q[find_joint(h, "slide")] = 0.2;
  q[find_joint(h, "slide mirror")] = -0.1;
  q[find_joint(h, "wrist roll")] = 12.0;
  const Eigen::VectorXd out = clamp_to_limits(h, q);
  EXPECT_DOUBLE_EQ(out[find_joint(h, "slide")], 0.05);
  EXPECT_DOUBLE_EQ(out[find_joint(h, "slide mirror")], 0.0);
  EXPECT_DOUBLE_EQ(out[find_joint(h, "wrist roll")], 12.0);
  const HandModel sah = load_hand("cordgrasp_sah");
  Eigen::VectorXd qs = Eigen::VectorXd::Constant(static_cast<Eigen::Index>(sah.joints.size()), 9.0);
  const Eigen::VectorXd outs = clamp_to_limits(sah, qs);
  for (size_t j = 0; j < sah.joints.size(); ++j) {
    if (sah.joints[j].is_moving()) {
      EXPECT_DOUBLE_EQ(outs[j], sah.joints[j].upper);
    }
  }
}

TEST(Kinematics, WrongSizedJointVectorThrows) {
  const HandModel h = load_hand(test::test_data("hands/two_link/two_link.yaml"));
  const Eigen::VectorXd q = Eigen::VectorXd::Zero(2);
  EXPECT_THROW(link_poses(h, q), std::invalid_argument);
  EXPECT_THROW(apply_couplings(h, q), std::invalid_argument);
  EXPECT_THROW(clamp_to_limits(h, q), std::invalid_argument);
}

TEST(Kinematics, RootPoseMovesTheWholeHandRigidly) {
  const HandModel h = load_hand("cordgrasp_sah");
  const Eigen::VectorXd q = apply_couplings(h, h.preshape);
  Eigen::Isometry3d X_WB = Eigen::Isometry3d::Identity();
  X_WB.rotate(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  X_WB.pretranslate(Eigen::Vector3d(0.3, -0.2, 0.5));
  const auto X0 = link_poses(h, q);
  const auto X1 = link_poses(h, q, X_WB);
  for (size_t l = 0; l < h.links.size(); ++l)
    EXPECT_TRUE((X_WB * X0[l]).isApprox(X1[l], 1e-12)) << h.links[l].name;
}

TEST(Kinematics, RootPoseForGcpPutsTheGcpOnTarget) {
  const HandModel h = load_hand("cordgrasp_sah");
  const Eigen::VectorXd q = apply_couplings(h, h.preshape);
  Eigen::Isometry3d X_WG = Eigen::Isometry3d::Identity();
  X_WG.rotate(Eigen::AngleAxisd(-1.1, Eigen::Vector3d(0.2, -1, 0.4).normalized()));
  X_WG.pretranslate(Eigen::Vector3d(0.05, 0.1, -0.2));
  const Eigen::Isometry3d X_WB = root_pose_for_gcp(h, q, X_WG);
  const Eigen::Isometry3d got = gcp_pose(h, link_poses(h, q, X_WB));
  EXPECT_LT((got.translation() - X_WG.translation()).norm(), kPosTol_m);
  EXPECT_LT((got.linear() - X_WG.linear()).norm(), 1e-9);
}

TEST(Kinematics, RevoluteJointRotatesItsChildAboutTheAxis) {
  const HandModel h = load_hand("cordgrasp_sah");
  Eigen::VectorXd q = apply_couplings(h, h.preshape);
  const int j = find_joint(h, "middle_proximal");
  const Joint& joint = h.joints[j];
  const auto X0 = link_poses(h, q);
  q[j] += 0.5;
  const auto X1 = link_poses(h, q);
  const Eigen::Isometry3d X_WJ = X0[joint.parent_link] * joint.X_PJ;
  // Points on the axis stay; the child frame turns by 0.5 rad about it.
  EXPECT_TRUE(X1[joint.child_link].translation().isApprox(X0[joint.child_link].translation()));
  const Eigen::Matrix3d dR =
      X1[joint.child_link].linear() * X0[joint.child_link].linear().transpose();
  const Eigen::AngleAxisd aa(dR);
  EXPECT_NEAR(aa.angle(), 0.5, 1e-12);
  EXPECT_TRUE(aa.axis().isApprox(X_WJ.linear() * joint.axis, 1e-9));
}

/// Virtual work Σ p_c(q)·f_c of forces at contacts that ride on their links, the contacts
/// given at q0 (couplings applied to both).
double contact_work(const HandModel& h, const Eigen::VectorXd& q0, const Eigen::VectorXd& q,
                    const Eigen::Isometry3d& X_OB, const std::vector<Contact>& contacts,
                    const std::vector<Eigen::Vector3d>& forces) {
  const auto X0 = link_poses(h, apply_couplings(h, q0), X_OB);
  const auto X1 = link_poses(h, apply_couplings(h, q), X_OB);
  double work = 0.0;
  for (size_t k = 0; k < contacts.size(); ++k)
    work += (X1[contacts[k].link] * (X0[contacts[k].link].inverse() * contacts[k].p_O))
                .dot(forces[k]);
  return work;
}

TEST(ContactForceTorques, EqualTheVirtualWorkOfTheContactForcesPooledOntoMasters) {
  for (const std::string& name :
       {std::string("cordgrasp_sah"), test::test_data("hands/features/features.yaml")}) {
    SCOPED_TRACE(name);
    const HandModel h = load_hand(name);
    Eigen::VectorXd q = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(h.joints.size()));
    for (size_t j = 0; j < h.joints.size(); ++j)
      if (h.joints[j].type == JointType::kRevolute || h.joints[j].type == JointType::kPrismatic)
        q[j] = 0.3 * h.joints[j].lower + 0.7 * h.joints[j].upper;
    Eigen::Isometry3d X_OB = Eigen::Isometry3d::Identity();
    X_OB.rotate(Eigen::AngleAxisd(0.9, Eigen::Vector3d(-1, 2, 0.5).normalized()));
    X_OB.pretranslate(Eigen::Vector3d(0.02, -0.07, 0.11));
    // One contact on every link below a moving joint, off the link origin, forces all different.
    const auto X_OL = link_poses(h, apply_couplings(h, q), X_OB);
    std::vector<Contact> contacts;
    std::vector<Eigen::Vector3d> forces;
    for (size_t l = 0; l < h.links.size(); ++l) {
      const int j = h.links[l].parent_joint;
      if (j < 0 || !h.joints[j].is_moving()) continue;
      const double k = static_cast<double>(contacts.size());
      Contact c;
      c.link = static_cast<int>(l);
      c.p_O = X_OL[l] * Eigen::Vector3d(0.01, 0.004 * k, -0.006);
      contacts.push_back(c);
      forces.push_back(Eigen::Vector3d(std::cos(k), std::sin(k), 0.5) * (1.0 + k));
    }
    ASSERT_GE(contacts.size(), 2u);
    const Eigen::VectorXd tau = contact_force_torques(h, q, X_OB, contacts, forces);
    constexpr double kStep = 1e-6;
    for (size_t j = 0; j < h.joints.size(); ++j) {
      if (h.joints[j].mimic || !h.joints[j].is_moving()) {
        EXPECT_EQ(tau[j], 0.0) << h.joints[j].name;
        continue;
      }
      Eigen::VectorXd qp = q, qm = q;
      qp[j] += kStep;
      qm[j] -= kStep;
      const double dwork = (contact_work(h, q, qp, X_OB, contacts, forces) -
                            contact_work(h, q, qm, X_OB, contacts, forces)) / (2.0 * kStep);
      EXPECT_NEAR(tau[j], dwork, 1e-6) << h.joints[j].name;
    }
  }
}

TEST(ContactForceTorques, ContactOnAnUnknownLinkOrAMissingForceThrows) {
  const HandModel h = load_hand("cordgrasp_sah");
  Contact c;
  c.link = static_cast<int>(h.links.size());
  const Eigen::Isometry3d I = Eigen::Isometry3d::Identity();
  EXPECT_THROW(contact_force_torques(h, h.preshape, I, {c}, {Eigen::Vector3d::UnitX()}),
               std::invalid_argument);
  c.link = h.root_link;
  EXPECT_THROW(contact_force_torques(h, h.preshape, I, {c}, {}), std::invalid_argument);
}

TEST(ContactLevers, BoundTheTorqueOfAUnitForceAtAContactAndReachItAcrossTheArm) {
  const HandModel h = load_hand("cordgrasp_sah");
  Eigen::VectorXd q = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(h.joints.size()));
  for (size_t j = 0; j < h.joints.size(); ++j)
    if (h.joints[j].type == JointType::kRevolute)
      q[j] = 0.4 * h.joints[j].lower + 0.6 * h.joints[j].upper;
  Eigen::Isometry3d X_OB = Eigen::Isometry3d::Identity();
  X_OB.rotate(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, -1, 2).normalized()));
  X_OB.pretranslate(Eigen::Vector3d(-0.03, 0.05, 0.08));
  const auto X_OL = link_poses(h, apply_couplings(h, q), X_OB);
  Contact c;
  c.link = find_link(h, "index_distal_link");
  c.p_O = X_OL[c.link] * Eigen::Vector3d(0.012, -0.003, 0.02);
  const Eigen::VectorXd lever = contact_levers(h, q, X_OB, {c});
  // A joint upstream of the contact with no mimic slave: its torque is the contact's alone.
  const int j = find_joint(h, "index_proximal");
  ASSERT_GT(lever[j], 0.0);
  const Eigen::Isometry3d X_OJ = X_OL[h.joints[j].parent_link] * h.joints[j].X_PJ;
  const Eigen::Vector3d axis = X_OJ.linear() * h.joints[j].axis;
  const Eigen::Vector3d across = axis.cross(c.p_O - X_OJ.translation()).normalized();
  EXPECT_NEAR(std::abs(contact_force_torques(h, q, X_OB, {c}, {across})[j]), lever[j], 1e-12);
  for (const Eigen::Vector3d& f : {Eigen::Vector3d(1, 2, 3).normalized(),
                                   Eigen::Vector3d(-2, 0.5, 1).normalized()})
    EXPECT_LE(std::abs(contact_force_torques(h, q, X_OB, {c}, {f})[j]), lever[j] + 1e-12);
  // Joints of other fingers carry none of it.
  EXPECT_EQ(lever[find_joint(h, "thumb_proximal")], 0.0);
  EXPECT_EQ(lever[find_joint(h, "ring_proximal")], 0.0);
  c.link = static_cast<int>(h.links.size());
  EXPECT_THROW(contact_levers(h, q, X_OB, {c}), std::invalid_argument);
}

}  // namespace
}  // namespace cordgrasp
