#pragma once

namespace cordgrasp {

/// Default Coulomb friction coefficient μ of finger–object contacts: the one value shared by the
/// planner's wrench space (spec §8, textbook mode) and the physics validation (issue 5).
inline constexpr double kDefaultFrictionCoefficient = 0.5;

/// Point-contact-with-friction model shared by the grasp wrench space (spec §8) and physics.
struct ContactModel {
  double mu = kDefaultFrictionCoefficient;  ///< Coulomb friction coefficient [-]
  int cone_edges = 8;                       ///< edges of the linearized friction cone (spec §8)
};

}  // namespace cordgrasp
