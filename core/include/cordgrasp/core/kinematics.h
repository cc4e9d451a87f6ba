#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "cordgrasp/core/grasp.h"
#include "cordgrasp/core/hand_model.h"

namespace cordgrasp {

/// Sets every mimic joint from its master: q[j] = multiplier·q[master] + offset.
/// @throws std::invalid_argument when q has the wrong size.
Eigen::VectorXd apply_couplings(const HandModel& hand, const Eigen::VectorXd& q);

/// Clamps every moving joint to [lower, upper] (continuous joints untouched).
/// @throws std::invalid_argument when q has the wrong size.
Eigen::VectorXd clamp_to_limits(const HandModel& hand, const Eigen::VectorXd& q);

/// Forward kinematics: world pose X_WL of every link for joint vector q (one entry per joint)
/// with the root link at X_WB. q is used as given; call apply_couplings first for mimic joints.
/// @throws std::invalid_argument when q has the wrong size.
std::vector<Eigen::Isometry3d> link_poses(const HandModel& hand, const Eigen::VectorXd& q,
                                          const Eigen::Isometry3d& X_WB =
                                              Eigen::Isometry3d::Identity());

/// World pose of the GCP given the link poses from link_poses().
Eigen::Isometry3d gcp_pose(const HandModel& hand, const std::vector<Eigen::Isometry3d>& X_WL);

/// Root pose X_WB that puts the GCP at X_WG for joint vector q.
Eigen::Isometry3d root_pose_for_gcp(const HandModel& hand, const Eigen::VectorXd& q,
                                    const Eigen::Isometry3d& X_WG);

/// Joint torques that make the hand exert force forces_O[c] (object frame, on the object) at
/// every contact c, at joint vector q (couplings applied here), the root link at X_OB in the
/// object frame: τ = Σ_c J_c(q)ᵀ·f_c over the joints upstream of each contact's link [N·m or N].
/// A mimic joint's torque is pooled onto its master (× multiplier), as its drive is the
/// master's; mimic entries are 0. Used by the physics squeeze (docs/physics.md §3).
/// @throws std::invalid_argument when q or forces_O have the wrong size or a contact names no
/// link.
Eigen::VectorXd contact_force_torques(const HandModel& hand, const Eigen::VectorXd& q,
                                      const Eigen::Isometry3d& X_OB,
                                      const std::vector<Contact>& contacts,
                                      const std::vector<Eigen::Vector3d>& forces_O);

/// Lever of every joint on the planned contacts, at joint vector q (couplings applied here),
/// the root link at X_OB: the largest distance from a revolute joint's axis to a contact on its
/// subtree [m], 1 for a prismatic joint with a contact on its subtree [-], 0 for joints with
/// none. A joint pushing with effort F·lever presses each of its contacts with at least F.
/// Mimic joints' levers are their own (not pooled). Used by the physics squeeze.
/// @throws std::invalid_argument when q has the wrong size or a contact names no link.
Eigen::VectorXd contact_levers(const HandModel& hand, const Eigen::VectorXd& q,
                               const Eigen::Isometry3d& X_OB,
                               const std::vector<Contact>& contacts);

}  // namespace cordgrasp
