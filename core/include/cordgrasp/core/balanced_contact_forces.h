#pragma once
#include <Eigen/Core>
#include <vector>

#include "cordgrasp/core/grasp.h"

namespace cordgrasp {

/// Contact forces that squeeze an object without moving it (internal forces of the grasp).
struct BalancedContactForces {
  /// Force of each contact on the object, object frame, scaled so that the largest normal
  /// component is 1 [relative]; empty when the contacts admit no such squeeze.
  std::vector<Eigen::Vector3d> forces_O;
  /// Smallest margin to a friction cone over the contacts: min_c (μ·f_n − ‖f_t‖) / ‖f_c‖
  /// [-]; ≥ 0 when every force lies within its cone and presses (f_n > 0).
  double cone_margin = -1.0;
  /// Whether every force presses and lies within its friction cone (cone_margin ≥ 0).
  bool within_cones() const { return !forces_O.empty() && cone_margin >= 0.0; }
};

/// The forces f_c at the contacts (each pressing along −n_c) whose sum and total moment vanish
/// and which are closest, in the least-squares sense, to equal presses along every inward
/// normal: the projection of (−n_1, …, −n_k) onto the null space of the grasp matrix. Friction
/// coefficient `mu` only for BalancedContactForces::cone_margin. Point contacts (no torsion).
BalancedContactForces balanced_contact_forces(const std::vector<Contact>& contacts, double mu);

}  // namespace cordgrasp
