#pragma once
// Hands built from URDF-style primitives in test code (no files): a two-finger parallel
// gripper and a three-finger hand.
#include <cmath>
#include <string>

#include "cordgrasp/core/hand_model.h"

namespace cordgrasp::test {

inline Geometry box_geometry(const Eigen::Vector3d& size, const Eigen::Vector3d& center) {
  Geometry g;
  g.kind = Geometry::Kind::kBox;
  g.box_size_m = size;
  g.X_LG.translation() = center;
  return g;
}

inline int add_link(HandModel& hand, const std::string& name, const Geometry& geometry) {
  Link link;
  link.name = name;
  link.collisions.push_back(geometry);
  link.visuals.push_back(geometry);
  link.inertial.mass_kg = 0.05;
  hand.links.push_back(link);
  return static_cast<int>(hand.links.size()) - 1;
}

inline int add_joint(HandModel& hand, const std::string& name, JointType type, int parent,
                     int child, const Eigen::Isometry3d& X_PJ, const Eigen::Vector3d& axis,
                     double lower, double upper) {
  Joint j;
  j.name = name;
  j.type = type;
  j.parent_link = parent;
  j.child_link = child;
  j.X_PJ = X_PJ;
  j.axis = axis.normalized();
  j.lower = lower;
  j.upper = upper;
  hand.joints.push_back(j);
  hand.links[static_cast<size_t>(child)].parent_joint = static_cast<int>(hand.joints.size()) - 1;
  return static_cast<int>(hand.joints.size()) - 1;
}

/// Palm 0.14 × 0.04 × 0.03 m below z = 0; two 0.01 × 0.02 × 0.08 m fingers standing on it,
/// inner faces at x = ∓0.055 when open (q = 0), closing along ±x by prismatic joints
/// (0 … 0.055 m, actor speed 0.05: 1 mm per closing step). GCP on the palm at z = 0.06, +z
/// between the fingers. Thumb: left finger.
inline HandModel make_parallel_gripper() {
  HandModel h;
  h.name = "test_parallel_gripper";
  const int palm = add_link(h, "palm", box_geometry({0.14, 0.04, 0.03}, {0, 0, -0.015}));
  const int left = add_link(h, "left", box_geometry({0.01, 0.02, 0.08}, {0, 0, 0.04}));
  const int right = add_link(h, "right", box_geometry({0.01, 0.02, 0.08}, {0, 0, 0.04}));
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() = Eigen::Vector3d(-0.06, 0, 0);
  const int jl = add_joint(h, "left_joint", JointType::kPrismatic, palm, left, X,
                           Eigen::Vector3d::UnitX(), 0.0, 0.055);
  X.translation() = Eigen::Vector3d(0.06, 0, 0);
  const int jr = add_joint(h, "right_joint", JointType::kPrismatic, palm, right, X,
                           -Eigen::Vector3d::UnitX(), 0.0, 0.055);
  h.gcp.link = palm;
  h.gcp.X_LG.translation() = Eigen::Vector3d(0, 0, 0.06);
  h.preshape = Eigen::VectorXd::Zero(2);
  h.actors.push_back({"left", {{jl, 0.05}}});
  h.actors.push_back({"right", {{jr, 0.05}}});
  h.thumb_links = {left};
  return h;
}

/// Disc-like palm (0.1 × 0.1 × 0.02 box below z = 0) with three two-link fingers at radius
/// 0.05 m, 120° apart, curling towards the axis (revolute 0 … 1.6 rad each); the distal joint
/// mimics the proximal one when `coupled`. GCP at z = 0.05 on the palm. Thumb: finger 0.
inline HandModel make_three_finger_hand(bool coupled = true) {
  HandModel h;
  h.name = "test_three_finger_hand";
  const int palm = add_link(h, "palm", box_geometry({0.1, 0.1, 0.02}, {0, 0, -0.01}));
  h.preshape = Eigen::VectorXd();
  std::vector<int> thumb;
  for (int f = 0; f < 3; ++f) {
    const double th = 2.0 * M_PI * f / 3.0;
    const Eigen::Vector3d axis(std::sin(th), -std::cos(th), 0.0);  // positive angle curls in
    const std::string name = "finger" + std::to_string(f);
    const int l1 =
        add_link(h, name + "_proximal", box_geometry({0.015, 0.015, 0.05}, {0, 0, 0.025}));
    const int l2 = add_link(h, name + "_distal", box_geometry({0.015, 0.015, 0.04}, {0, 0, 0.02}));
    Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
    X.translation() = Eigen::Vector3d(0.05 * std::cos(th), 0.05 * std::sin(th), 0.0);
    const int j1 =
        add_joint(h, name + "_joint1", JointType::kRevolute, palm, l1, X, axis, 0.0, 1.6);
    X.translation() = Eigen::Vector3d(0, 0, 0.052);
    const int j2 = add_joint(h, name + "_joint2", JointType::kRevolute, l1, l2, X, axis, 0.0, 1.6);
    Actor actor{name, {{j1, 1.0}}};
    if (coupled)
      h.joints[static_cast<size_t>(j2)].mimic = Mimic{j1, 1.0, 0.0};
    else
      actor.joints.push_back({j2, 1.0});
    h.actors.push_back(actor);
    if (f == 0) thumb = {l1, l2};
  }
  h.gcp.link = palm;
  h.gcp.X_LG.translation() = Eigen::Vector3d(0, 0, 0.05);
  h.preshape = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(h.joints.size()));
  h.thumb_links = thumb;
  return h;
}

}  // namespace cordgrasp::test
