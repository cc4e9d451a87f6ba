#pragma once
#include <Eigen/Core>

#include "cordgrasp/core/contact_model.h"
#include "cordgrasp/core/grasp.h"
#include "cordgrasp/core/hand_model.h"

namespace cordgrasp {

/// The load a grasp must hold statically: the object's weight at its centre of mass.
struct StaticLoad {
  Eigen::Vector3d com_O_m = Eigen::Vector3d::Zero();     ///< centre of mass, object frame [m]
  Eigen::Vector3d weight_O_N = Eigen::Vector3d::Zero();  ///< m·g, object frame [N]
};

/// Weight margin of a planned grasp (docs/finger-stage-and-quality.md, "Weight margin"): the
/// largest s in [0, max_margin] for which forces at the planned contacts, each inside its
/// linearized friction cone (`contact`, torsion of soft fingers included), balance s × the
/// load while every joint's torque Σ_c J_cᵀ f_c (contact_force_torques, at grasp.q) stays
/// within ±effort_limits[j]. Entries that are not finite or ≤ 0 do not bound their joint
/// (a locked or rigid joint); contacts on the root link press with any force. Below 1 the hand
/// cannot hold the object's weight at those contacts whatever its grip; 0 also when no forces
/// balance the load at all. Solved as a linear program (GLPK's simplex).
/// @throws std::invalid_argument when effort_limits has the wrong size or a contact names no link.
double weight_margin(const HandModel& hand, const Grasp& grasp, const ContactModel& contact,
                     const StaticLoad& load, const Eigen::VectorXd& effort_limits,
                     double max_margin = 100.0);

}  // namespace cordgrasp
