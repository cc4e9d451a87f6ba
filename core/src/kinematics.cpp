#include "cordgrasp/core/kinematics.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace cordgrasp {
namespace {
void check_size(const HandModel& hand, const Eigen::VectorXd& q, const char* who) {
  if (q.size() != static_cast<Eigen::Index>(hand.joints.size()))
    throw std::invalid_argument(std::string(who) + ": q has " + std::to_string(q.size()) +
                                " entries, hand '" + hand.name + "' has " +
                                std::to_string(hand.joints.size()) + " joints");
}
}  // namespace

Eigen::VectorXd apply_couplings(const HandModel& hand, const Eigen::VectorXd& q) {
  check_size(hand, q, "apply_couplings");
  Eigen::VectorXd out = q;
  // Joints are in topological order, but a mimic master can sit anywhere; masters are never
  // mimic joints themselves (checked at load), so one pass suffices.
  for (size_t j = 0; j < hand.joints.size(); ++j) {
    const auto& m = hand.joints[j].mimic;
    if (m) out[j] = m->multiplier * q[m->master_joint] + m->offset;
  }
  return out;
}

Eigen::VectorXd clamp_to_limits(const HandModel& hand, const Eigen::VectorXd& q) {
  check_size(hand, q, "clamp_to_limits");
  Eigen::VectorXd out = q;
  for (size_t j = 0; j < hand.joints.size(); ++j) {
    const Joint& joint = hand.joints[j];
    if (joint.type == JointType::kRevolute || joint.type == JointType::kPrismatic)
      out[j] = std::clamp(out[j], joint.lower, joint.upper);
  }
  return out;
}

namespace {
Eigen::Isometry3d joint_motion(const Joint& joint, double value) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  switch (joint.type) {
    case JointType::kRevolute:
    case JointType::kContinuous:
      X.linear() = Eigen::AngleAxisd(value, joint.axis).toRotationMatrix();
      break;
    case JointType::kPrismatic:
      X.translation() = value * joint.axis;
      break;
    case JointType::kFixed:
      break;
  }
  return X;
}
}  // namespace

std::vector<Eigen::Isometry3d> link_poses(const HandModel& hand, const Eigen::VectorXd& q,
                                          const Eigen::Isometry3d& X_WB) {
  check_size(hand, q, "link_poses");
  std::vector<Eigen::Isometry3d> X_WL(hand.links.size(), Eigen::Isometry3d::Identity());
  X_WL[hand.root_link] = X_WB;
  for (size_t j = 0; j < hand.joints.size(); ++j) {
    const Joint& joint = hand.joints[j];
    X_WL[joint.child_link] = X_WL[joint.parent_link] * joint.X_PJ * joint_motion(joint, q[j]);
  }
  return X_WL;
}

Eigen::Isometry3d gcp_pose(const HandModel& hand, const std::vector<Eigen::Isometry3d>& X_WL) {
  return X_WL.at(hand.gcp.link) * hand.gcp.X_LG;
}

Eigen::Isometry3d root_pose_for_gcp(const HandModel& hand, const Eigen::VectorXd& q,
                                    const Eigen::Isometry3d& X_WG) {
  const Eigen::Isometry3d X_BG = gcp_pose(hand, link_poses(hand, q));
  return X_WG * X_BG.inverse();
}

Eigen::VectorXd contact_force_torques(const HandModel& hand, const Eigen::VectorXd& q,
                                      const Eigen::Isometry3d& X_OB,
                                      const std::vector<Contact>& contacts,
                                      const std::vector<Eigen::Vector3d>& forces_O) {
  check_size(hand, q, "contact_force_torques");
  if (forces_O.size() != contacts.size())
    throw std::invalid_argument("contact_force_torques: " + std::to_string(forces_O.size()) +
                                " forces for " + std::to_string(contacts.size()) + " contacts");
  const std::vector<Eigen::Isometry3d> X_OL = link_poses(hand, apply_couplings(hand, q), X_OB);
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(q.size());
  for (size_t k = 0; k < contacts.size(); ++k) {
    const Contact& c = contacts[k];
    if (c.link < 0 || c.link >= static_cast<int>(hand.links.size()))
      throw std::invalid_argument("contact_force_torques: contact on link " +
                                  std::to_string(c.link) + ", hand '" + hand.name + "' has " +
                                  std::to_string(hand.links.size()) + " links");
    const Eigen::Vector3d& force = forces_O[k];
    for (int j = hand.links[c.link].parent_joint; j >= 0;
         j = hand.links[hand.joints[j].parent_link].parent_joint) {
      const Joint& joint = hand.joints[j];
      const Eigen::Isometry3d X_OJ = X_OL[joint.parent_link] * joint.X_PJ;
      const Eigen::Vector3d axis = X_OJ.linear() * joint.axis;
      switch (joint.type) {
        case JointType::kRevolute:
        case JointType::kContinuous:
          tau[j] += axis.dot((c.p_O - X_OJ.translation()).cross(force));
          break;
        case JointType::kPrismatic:
          tau[j] += axis.dot(force);
          break;
        case JointType::kFixed:
          break;
      }
    }
  }
  for (size_t j = 0; j < hand.joints.size(); ++j) {
    const auto& m = hand.joints[j].mimic;
    if (!m) continue;
    tau[m->master_joint] += m->multiplier * tau[static_cast<Eigen::Index>(j)];
    tau[static_cast<Eigen::Index>(j)] = 0.0;
  }
  return tau;
}

Eigen::VectorXd contact_levers(const HandModel& hand, const Eigen::VectorXd& q,
                               const Eigen::Isometry3d& X_OB,
                               const std::vector<Contact>& contacts) {
  check_size(hand, q, "contact_levers");
  const std::vector<Eigen::Isometry3d> X_OL = link_poses(hand, apply_couplings(hand, q), X_OB);
  Eigen::VectorXd lever = Eigen::VectorXd::Zero(q.size());
  for (const Contact& c : contacts) {
    if (c.link < 0 || c.link >= static_cast<int>(hand.links.size()))
      throw std::invalid_argument("contact_levers: contact on link " + std::to_string(c.link) +
                                  ", hand '" + hand.name + "' has " +
                                  std::to_string(hand.links.size()) + " links");
    for (int j = hand.links[c.link].parent_joint; j >= 0;
         j = hand.links[hand.joints[j].parent_link].parent_joint) {
      const Joint& joint = hand.joints[j];
      const Eigen::Isometry3d X_OJ = X_OL[joint.parent_link] * joint.X_PJ;
      const Eigen::Vector3d axis = (X_OJ.linear() * joint.axis).normalized();
      double arm = 0.0;
      switch (joint.type) {
        case JointType::kRevolute:
        case JointType::kContinuous: {
          const Eigen::Vector3d r = c.p_O - X_OJ.translation();
          arm = (r - axis * axis.dot(r)).norm();
          break;
        }
        case JointType::kPrismatic:
          arm = 1.0;
          break;
        case JointType::kFixed:
          break;
      }
      lever[j] = std::max(lever[j], arm);
    }
  }
  return lever;
}

}  // namespace cordgrasp
