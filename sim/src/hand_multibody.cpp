#include "hand_multibody.h"

#include <Eigen/Eigenvalues>
#include <stdexcept>
#include <string>

namespace cordgrasp::bullet {

namespace {

/// A body with no mass in the URDF gets this much (Bullet needs positive masses) [kg].
constexpr double kMinBodyMass_kg = 1e-3;
/// Principal moments are floored at this fraction of the largest (thin rods, point masses).
constexpr double kMinInertiaRatio = 1e-3;
/// Absolute floor of principal moments [kg·m²].
constexpr double kMinInertia_kgm2 = 1e-10;

/// Motion of a moving joint at value q, in the joint frame.
Eigen::Isometry3d joint_motion(const Joint& joint, double q) {
  Eigen::Isometry3d M = Eigen::Isometry3d::Identity();
  if (joint.type == JointType::kPrismatic)
    M.translation() = q * joint.axis.normalized();
  else if (joint.is_moving())
    M.linear() = Eigen::AngleAxisd(q, joint.axis.normalized()).toRotationMatrix();
  return M;
}

btQuaternion to_bt_quaternion(const Eigen::Matrix3d& R) {
  const Eigen::Quaterniond q(R);
  return btQuaternion(q.x(), q.y(), q.z(), q.w());
}

/// Mass, centre of mass and principal frame of a group of links (frame R of the group's
/// reference link).
struct BodyInertia {
  double mass = 0.0;
  Eigen::Isometry3d X_RC = Eigen::Isometry3d::Identity();  ///< COM principal frame in R
  Eigen::Vector3d principal = Eigen::Vector3d::Zero();     ///< diagonal inertia in C
};

BodyInertia body_inertia(const HandModel& hand, const std::vector<int>& members,
                         const std::vector<Eigen::Isometry3d>& X_RL, const Joint* joint,
                         double armature_kgm2, double armature_kg) {
  BodyInertia out;
  Eigen::Vector3d mc = Eigen::Vector3d::Zero();
  for (int l : members) {
    const Inertial& in = hand.links[static_cast<size_t>(l)].inertial;
    const double m = std::max(0.0, in.mass_kg);
    out.mass += m;
    mc += m * (X_RL[static_cast<size_t>(l)] * in.com_m);
  }
  Eigen::Vector3d com = Eigen::Vector3d::Zero();
  if (out.mass > 0.0) {
    com = mc / out.mass;
  } else {
    for (int l : members) com += X_RL[static_cast<size_t>(l)].translation();
    com /= static_cast<double>(members.size());
  }
  Eigen::Matrix3d I = Eigen::Matrix3d::Zero();
  for (int l : members) {
    const Inertial& in = hand.links[static_cast<size_t>(l)].inertial;
    const double m = std::max(0.0, in.mass_kg);
    const Eigen::Matrix3d R = X_RL[static_cast<size_t>(l)].linear();
    const Eigen::Vector3d d = X_RL[static_cast<size_t>(l)] * in.com_m - com;
    I += R * in.inertia_kgm2 * R.transpose() +
         m * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  }
  if (out.mass < kMinBodyMass_kg) {
    out.mass = kMinBodyMass_kg;
    I = Eigen::Matrix3d::Identity() * (0.4 * kMinBodyMass_kg * 0.005 * 0.005);
  }
  // Reflected actuator inertia: about the joint axis (the body's frame R is the joint frame at
  // q = 0), or as mass for a prismatic joint (its weight is compensated like the rest).
  if (joint && joint->type == JointType::kPrismatic) {
    out.mass += armature_kg;
  } else if (joint && joint->is_moving()) {
    const Eigen::Vector3d a = joint->axis.normalized();
    I += armature_kgm2 * a * a.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(0.5 * (I + I.transpose()));
  Eigen::Matrix3d V = eig.eigenvectors();
  if (V.determinant() < 0.0) V.col(2) = -V.col(2);
  Eigen::Vector3d lambda = eig.eigenvalues();
  const double floor = std::max(kMinInertia_kgm2, kMinInertiaRatio * lambda.maxCoeff());
  for (int a = 0; a < 3; ++a) lambda[a] = std::max(lambda[a], floor);
  out.X_RC.linear() = V;
  out.X_RC.translation() = com;
  out.principal = lambda;
  return out;
}

}  // namespace

std::unique_ptr<HandMultiBody> make_hand_multibody(const HandModel& hand,
                                                   const HandBodyParams& params) {
  const int num_links = static_cast<int>(hand.links.size());
  if (num_links == 0) throw std::invalid_argument("make_hand_multibody: hand has no links");
  auto out = std::make_unique<HandMultiBody>();
  // Group links rigidly joined by fixed joints; body 0 is the root's group.
  out->link_body.assign(static_cast<size_t>(num_links), -1);
  std::vector<Eigen::Isometry3d> X_RL(static_cast<size_t>(num_links),
                                      Eigen::Isometry3d::Identity());
  std::vector<int> body_joint = {-1};  // moving joint into each body (-1: base)
  out->root_link = hand.root_link;
  out->link_body[static_cast<size_t>(hand.root_link)] = 0;
  // Locked joints, and mimic joints whose master is locked, are merged like fixed joints.
  std::vector<bool> lock(hand.joints.size(), false);
  for (size_t j = 0; j < hand.joints.size() && j < params.locked.size(); ++j)
    lock[j] = params.locked[j] && hand.joints[j].is_moving();
  for (size_t j = 0; j < hand.joints.size(); ++j) {
    const auto& mimic = hand.joints[j].mimic;
    if (mimic && mimic->master_joint >= 0 &&
        mimic->master_joint < static_cast<int>(hand.joints.size()) &&
        lock[static_cast<size_t>(mimic->master_joint)])
      lock[j] = hand.joints[j].is_moving();
  }
  out->joint_mb_link.assign(hand.joints.size(), -1);
  out->merged_q = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(hand.joints.size()));
  for (size_t j = 0; j < hand.joints.size(); ++j) {
    const Joint& joint = hand.joints[j];
    if (joint.parent_link < 0 || joint.parent_link >= num_links || joint.child_link < 0 ||
        joint.child_link >= num_links || out->link_body[static_cast<size_t>(joint.parent_link)] < 0)
      throw std::invalid_argument("make_hand_multibody: joint '" + joint.name +
                                  "' has an unknown or unreached parent link");
    const size_t p = static_cast<size_t>(joint.parent_link);
    const size_t c = static_cast<size_t>(joint.child_link);
    const bool locked = lock[j];
    if (!joint.is_moving() || locked) {
      out->link_body[c] = out->link_body[p];
      if (locked) out->merged_q[static_cast<Eigen::Index>(j)] = params.lock_values[static_cast<Eigen::Index>(j)];
      X_RL[c] = X_RL[p] * joint.X_PJ *
                (locked ? joint_motion(joint, params.lock_values[static_cast<Eigen::Index>(j)])
                        : Eigen::Isometry3d::Identity());
    } else {
      out->link_body[c] = static_cast<int>(body_joint.size());
      out->joint_mb_link[j] = static_cast<int>(body_joint.size()) - 1;
      body_joint.push_back(static_cast<int>(j));
    }
  }
  const int num_bodies = static_cast<int>(body_joint.size());
  std::vector<std::vector<int>> members(static_cast<size_t>(num_bodies));
  for (int l = 0; l < num_links; ++l) {
    const int b = out->link_body[static_cast<size_t>(l)];
    if (b < 0) {  // unreached link (not in the tree): treat as part of the base, unused
      out->link_body[static_cast<size_t>(l)] = 0;
      continue;
    }
    members[static_cast<size_t>(b)].push_back(l);
  }
  std::vector<BodyInertia> inertia(static_cast<size_t>(num_bodies));
  out->X_CL.assign(static_cast<size_t>(num_links), Eigen::Isometry3d::Identity());
  for (int b = 0; b < num_bodies; ++b) {
    const int bj = body_joint[static_cast<size_t>(b)];
    inertia[static_cast<size_t>(b)] =
        body_inertia(hand, members[static_cast<size_t>(b)], X_RL,
                     bj >= 0 ? &hand.joints[static_cast<size_t>(bj)] : nullptr,
                     params.sim.armature_kgm2, params.sim.armature_kg);
    for (int l : members[static_cast<size_t>(b)])
      out->X_CL[static_cast<size_t>(l)] =
          inertia[static_cast<size_t>(b)].X_RC.inverse() * X_RL[static_cast<size_t>(l)];
    out->body_mass_kg.push_back(inertia[static_cast<size_t>(b)].mass);
    out->total_mass_kg += inertia[static_cast<size_t>(b)].mass;
  }

  // The multibody: floating base, one link per moving joint.
  const BodyInertia& base = inertia[0];
  out->mb = std::make_unique<btMultiBody>(num_bodies - 1, base.mass * params.sim.base_mass_scale,
                                          to_bt(Eigen::Vector3d(base.principal *
                                                                params.sim.base_mass_scale)),
                                          /*fixedBase=*/false, /*canSleep=*/false);
  out->mb->setHasSelfCollision(false);
  out->mb->setLinearDamping(0.0);
  out->mb->setAngularDamping(0.0);
  out->mb->setUseGyroTerm(true);
  out->mb_link_joint.assign(static_cast<size_t>(num_bodies - 1), -1);
  for (int b = 1; b < num_bodies; ++b) {
    const int j = body_joint[static_cast<size_t>(b)];
    const Joint& joint = hand.joints[static_cast<size_t>(j)];
    const int i = b - 1;
    out->mb_link_joint[static_cast<size_t>(i)] = j;
    const int parent_body = out->link_body[static_cast<size_t>(joint.parent_link)];
    // Joint frame J in the parent body's COM frame; the child link frame is J at q = 0.
    const Eigen::Isometry3d X_CpJ = out->X_CL[static_cast<size_t>(joint.parent_link)] * joint.X_PJ;
    const Eigen::Isometry3d& X_JC = inertia[static_cast<size_t>(b)].X_RC;
    const Eigen::Matrix3d R_CJ = X_JC.linear().transpose();
    const btQuaternion rot_parent_to_this =
        to_bt_quaternion((X_CpJ.linear() * X_JC.linear()).transpose());
    const btVector3 axis = to_bt(Eigen::Vector3d(R_CJ * joint.axis.normalized()));
    const btVector3 parent_com_to_pivot = to_bt(Eigen::Vector3d(X_CpJ.translation()));
    const btVector3 pivot_to_com = to_bt(Eigen::Vector3d(R_CJ * X_JC.translation()));
    const BodyInertia& in = inertia[static_cast<size_t>(b)];
    if (joint.type == JointType::kPrismatic)
      out->mb->setupPrismatic(i, in.mass, to_bt(in.principal), parent_body - 1,
                              rot_parent_to_this, axis, parent_com_to_pivot, pivot_to_com,
                              /*disableParentCollision=*/true);
    else
      out->mb->setupRevolute(i, in.mass, to_bt(in.principal), parent_body - 1,
                             rot_parent_to_this, axis, parent_com_to_pivot, pivot_to_com,
                             /*disableParentCollision=*/true);
  }
  out->mb->finalizeMultiDof();

  // Collision shapes (the planner's, merged per body, in the COM frame) and colliders.
  out->shapes.resize(static_cast<size_t>(num_bodies));
  out->colliders.resize(static_cast<size_t>(num_bodies));
  for (int b = 0; b < num_bodies; ++b) {
    std::vector<const Link*> links;
    std::vector<Eigen::Isometry3d> X_CLs;
    for (int l : members[static_cast<size_t>(b)]) {
      links.push_back(&hand.links[static_cast<size_t>(l)]);
      X_CLs.push_back(out->X_CL[static_cast<size_t>(l)]);
    }
    out->shapes[static_cast<size_t>(b)] = make_links_shape(links, X_CLs, ShapeParams{params.sim.link_margin_m});
    btCompoundShape* compound = out->shapes[static_cast<size_t>(b)].compound.get();
    if (!compound) continue;
    if (params.sim.polyhedral_contacts)
      for (auto& child : out->shapes[static_cast<size_t>(b)].children)
        if (child->isPolyhedral())
          static_cast<btPolyhedralConvexShape*>(child.get())->initializePolyhedralFeatures();
    auto collider = std::make_unique<btMultiBodyLinkCollider>(out->mb.get(), b - 1);
    collider->setCollisionShape(compound);
    collider->setFriction(params.link_friction);
    collider->setRestitution(0.0);
    collider->setRollingFriction(0.0);
    collider->setSpinningFriction(0.0);
    collider->setCollisionFlags(collider->getCollisionFlags() |
                                btCollisionObject::CF_HAS_FRICTION_ANCHOR);
    if (b == 0)
      out->mb->setBaseCollider(collider.get());
    else
      out->mb->getLink(b - 1).m_collider = collider.get();
    out->colliders[static_cast<size_t>(b)] = std::move(collider);
  }

  // Limits, servos (one per driven joint) and mimic gears.
  const double dt = params.sim.time_step_s;
  out->effort_limit.assign(hand.joints.size(), 0.0);
  out->joint_motor.assign(hand.joints.size(), -1);
  for (size_t j = 0; j < hand.joints.size(); ++j) {
    const Joint& joint = hand.joints[j];
    const int i = out->joint_mb_link[j];
    if (i < 0) continue;
    const double fallback = joint.type == JointType::kPrismatic ? params.sim.default_effort_N
                                                                 : params.sim.default_effort_Nm;
    out->effort_limit[j] =
        params.sim.effort_scale * (joint.effort_limit > 0.0 ? joint.effort_limit : fallback);
    if (joint.type != JointType::kContinuous && std::isfinite(joint.lower) &&
        std::isfinite(joint.upper)) {
      auto limit = std::make_unique<btMultiBodyJointLimitConstraint>(out->mb.get(), i,
                                                                     joint.lower, joint.upper);
      limit->setMaxAppliedImpulse(params.constraint_max_force_N * dt);
      out->limits.push_back(std::move(limit));
    }
    if (joint.mimic) {
      const int master = joint.mimic->master_joint;
      const int mi = master >= 0 && master < static_cast<int>(hand.joints.size())
                         ? out->joint_mb_link[static_cast<size_t>(master)]
                         : -1;
      if (mi < 0)
        throw std::invalid_argument("make_hand_multibody: mimic joint '" + joint.name +
                                    "' has no moving master");
      // Gear row: q̇_slave + ratio·q̇_master = 0 and q_slave + ratio·q_master = target.
      auto gear = std::make_unique<btMultiBodyGearConstraint>(
          out->mb.get(), i, out->mb.get(), mi, btVector3(0, 0, 0), btVector3(0, 0, 0),
          btMatrix3x3::getIdentity(), btMatrix3x3::getIdentity());
      gear->setGearRatio(-joint.mimic->multiplier);
      gear->setRelativePositionTarget(joint.mimic->offset);
      gear->setErp(params.sim.gear_erp);
      gear->setMaxAppliedImpulse(params.constraint_max_force_N * dt);
      out->gears.push_back(std::move(gear));
      out->gear_joint.push_back(static_cast<int>(j));
      continue;
    }
    auto motor = std::make_unique<btMultiBodyJointMotor>(out->mb.get(), i, 0.0,
                                                         out->effort_limit[j] * dt);
    out->joint_motor[j] = static_cast<int>(out->motors.size());
    out->motors.push_back(std::move(motor));
    out->motor_joint.push_back(static_cast<int>(j));
  }
  // A coupled set is driven by its master's actuator: the mimic joints' effort limits add to
  // the master's (their gears pass the torque on), so the set keeps the URDF's total capacity.
  if (params.pool_mimic_efforts)
    for (size_t k = 0; k < out->gears.size(); ++k) {
      const Joint& slave = hand.joints[static_cast<size_t>(out->gear_joint[k])];
      const int master = slave.mimic->master_joint;
      if (out->joint_motor[static_cast<size_t>(master)] >= 0)
        out->effort_limit[static_cast<size_t>(master)] +=
            std::abs(slave.mimic->multiplier) * out->effort_limit[static_cast<size_t>(out->gear_joint[k])];
    }
  for (size_t k = 0; k < out->motors.size(); ++k)
    out->motors[k]->setMaxAppliedImpulse(out->effort_limit[static_cast<size_t>(out->motor_joint[k])] * dt);
  return out;
}

namespace {

void update_colliders(btMultiBody& mb) {
  btAlignedObjectArray<btQuaternion> world_to_local;
  btAlignedObjectArray<btVector3> local_origin;
  mb.forwardKinematics(world_to_local, local_origin);
  mb.updateCollisionObjectWorldTransforms(world_to_local, local_origin);
}

}  // namespace

void place_hand(HandMultiBody& body, const Eigen::Isometry3d& X_WB, const Eigen::VectorXd& q) {
  btMultiBody& mb = *body.mb;
  // Root link at X_WB: base COM frame at X_WB · X_CL[root]⁻¹ (the root is in body 0).
  mb.setBaseWorldTransform(
      to_bt(Eigen::Isometry3d(X_WB * body.X_CL[static_cast<size_t>(body.root_link)].inverse())));
  mb.setBaseVel(btVector3(0, 0, 0));
  mb.setBaseOmega(btVector3(0, 0, 0));
  for (int i = 0; i < mb.getNumLinks(); ++i) {
    const int j = body.mb_link_joint[static_cast<size_t>(i)];
    mb.setJointPos(i, q[j]);
    mb.setJointVel(i, 0.0);
  }
  update_colliders(mb);
}

Eigen::Isometry3d body_pose(const HandMultiBody& body, int b) {
  const btMultiBody& mb = *body.mb;
  if (b == 0) return from_bt(mb.getBaseWorldTransform());
  const int i = b - 1;
  btTransform X;
  X.setOrigin(mb.localPosToWorld(i, btVector3(0, 0, 0)));
  X.setBasis(mb.localFrameToWorld(i, btMatrix3x3::getIdentity()));
  return from_bt(X);
}

Eigen::Isometry3d root_pose(const HandMultiBody& body) {
  return body_pose(body, 0) * body.X_CL[static_cast<size_t>(body.root_link)];
}

std::vector<Eigen::Isometry3d> hand_link_poses(const HandMultiBody& body) {
  const int num_bodies = body.mb->getNumLinks() + 1;
  std::vector<Eigen::Isometry3d> X_WC(static_cast<size_t>(num_bodies));
  for (int b = 0; b < num_bodies; ++b) X_WC[static_cast<size_t>(b)] = body_pose(body, b);
  std::vector<Eigen::Isometry3d> out(body.link_body.size());
  for (size_t l = 0; l < out.size(); ++l)
    out[l] = X_WC[static_cast<size_t>(body.link_body[l])] * body.X_CL[l];
  return out;
}

Eigen::VectorXd hand_joint_positions(const HandMultiBody& body, int num_joints) {
  Eigen::VectorXd q = body.merged_q.size() == num_joints ? body.merged_q
                                                         : Eigen::VectorXd::Zero(num_joints);
  for (int i = 0; i < body.mb->getNumLinks(); ++i)
    q[body.mb_link_joint[static_cast<size_t>(i)]] = body.mb->getJointPos(i);
  return q;
}

Eigen::VectorXd hand_joint_velocities(const HandMultiBody& body, int num_joints) {
  Eigen::VectorXd v = Eigen::VectorXd::Zero(num_joints);
  for (int i = 0; i < body.mb->getNumLinks(); ++i)
    v[body.mb_link_joint[static_cast<size_t>(i)]] = body.mb->getJointVel(i);
  return v;
}

void add_hand_to_world(HandMultiBody& body, btMultiBodyDynamicsWorld& world, int group,
                       int mask) {
  world.addMultiBody(body.mb.get(), group, mask);
  for (auto& collider : body.colliders)
    if (collider) world.addCollisionObject(collider.get(), group, mask);
  for (auto& c : body.limits) world.addMultiBodyConstraint(c.get());
  for (auto& c : body.gears) world.addMultiBodyConstraint(c.get());
  for (auto& c : body.motors) world.addMultiBodyConstraint(c.get());
}

void remove_hand_from_world(HandMultiBody& body, btMultiBodyDynamicsWorld& world) {
  for (auto& c : body.motors) world.removeMultiBodyConstraint(c.get());
  for (auto& c : body.gears) world.removeMultiBodyConstraint(c.get());
  for (auto& c : body.limits) world.removeMultiBodyConstraint(c.get());
  for (auto& collider : body.colliders)
    if (collider) world.removeCollisionObject(collider.get());
  world.removeMultiBody(body.mb.get());
}

}  // namespace cordgrasp::bullet
