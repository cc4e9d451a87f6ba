#pragma once
// sim-internal: HandModel → btMultiBody (docs/physics.md §2). Links joined by fixed joints are
// merged into one body; every body's frame is its principal inertia frame at its centre of mass
// (Bullet wants diagonal inertias). Collision shapes come from bullet_shapes (the planner's
// shapes).
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyGearConstraint.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointLimitConstraint.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointMotor.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include <memory>
#include <vector>

#include "bullet_shapes.h"
#include "cordgrasp/sim/sim_params.h"
#include "cordgrasp/core/hand_model.h"

namespace cordgrasp::bullet {

/// How the hand multibody is built.
struct HandBodyParams {
  /// The simulation's settings the hand body is built from: link margin, time step (motor
  /// impulse caps are effort × time step), default efforts and effort scale, gear ERP, base
  /// mass scale, armature, polyhedral contacts.
  SimParams sim;
  double constraint_max_force_N = 2000.0;  ///< force cap of joint limits and gears [N or N·m]
  double link_friction = 1.0;        ///< Bullet friction of the links (× the object's)
  bool pool_mimic_efforts = true;    ///< mimic joints' effort limits add to their master's
  /// Per HandModel joint (empty: none): lock this moving joint at `lock_values[j]`, i.e. build
  /// it as a fixed joint (merged into its parent body).
  std::vector<bool> locked;
  Eigen::VectorXd lock_values;
};

/// A hand as a btMultiBody with its colliders and constraints. Bodies: 0 = base (the root
/// link's group), b ≥ 1 = multibody link b − 1.
struct HandMultiBody {
  std::unique_ptr<btMultiBody> mb;
  int root_link = 0;                    ///< HandModel root link (in body 0)
  std::vector<int> link_body;           ///< HandModel link → body
  std::vector<Eigen::Isometry3d> X_CL;  ///< HandModel link frame in its body's COM frame C
  std::vector<int> joint_mb_link;       ///< HandModel joint → multibody link, -1 when merged
  Eigen::VectorXd merged_q;             ///< values of merged joints (locked ones; fixed: 0)
  std::vector<int> mb_link_joint;       ///< multibody link → HandModel joint
  std::vector<LinkShape> shapes;        ///< per body (compound nullptr: no geometry)
  std::vector<std::unique_ptr<btMultiBodyLinkCollider>> colliders;  ///< per body, may be null
  std::vector<std::unique_ptr<btMultiBodyJointLimitConstraint>> limits;
  std::vector<std::unique_ptr<btMultiBodyGearConstraint>> gears;  ///< mimic couplings
  std::vector<int> gear_joint;          ///< slave HandModel joint of each gear
  std::vector<std::unique_ptr<btMultiBodyJointMotor>> motors;  ///< one per driven joint
  std::vector<int> motor_joint;         ///< HandModel joint of each motor
  std::vector<int> joint_motor;         ///< HandModel joint → motor index, -1 when none
  std::vector<double> effort_limit;     ///< per HandModel joint, defaults and scale applied
  std::vector<double> body_mass_kg;     ///< per body
  double total_mass_kg = 0.0;
};

/// Builds the multibody (not yet in a world). @throws std::invalid_argument when the hand has
/// no links or a joint's parent is unknown.
std::unique_ptr<HandMultiBody> make_hand_multibody(const HandModel& hand,
                                                   const HandBodyParams& params);

/// Puts the root link at X_WB and the joints at q (one entry per HandModel joint), velocities
/// zero, colliders updated. Meant for initial placement only: the simulation moves the base
/// by commanding its velocity.
void place_hand(HandMultiBody& body, const Eigen::Isometry3d& X_WB, const Eigen::VectorXd& q);

/// World pose of body b's COM frame.
Eigen::Isometry3d body_pose(const HandMultiBody& body, int b);

/// World pose of the root link.
Eigen::Isometry3d root_pose(const HandMultiBody& body);

/// World poses of every HandModel link, from Bullet's state.
std::vector<Eigen::Isometry3d> hand_link_poses(const HandMultiBody& body);

/// Joint vector from Bullet (merged fixed joints: 0), one entry per HandModel joint.
Eigen::VectorXd hand_joint_positions(const HandMultiBody& body, int num_joints);

/// Joint velocities, one entry per HandModel joint (fixed: 0).
Eigen::VectorXd hand_joint_velocities(const HandMultiBody& body, int num_joints);

/// Adds the multibody, its colliders (group/mask as given) and constraints to the world.
void add_hand_to_world(HandMultiBody& body, btMultiBodyDynamicsWorld& world, int group,
                       int mask);

/// Removes everything add_hand_to_world() added.
void remove_hand_from_world(HandMultiBody& body, btMultiBodyDynamicsWorld& world);

}  // namespace cordgrasp::bullet
