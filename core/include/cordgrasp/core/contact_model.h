#pragma once
#include "cordgrasp/core/serialize.h"

namespace cordgrasp {

/// Default Coulomb friction coefficient μ of finger–object contacts: the one value shared by the
/// planner's wrench space (docs/algorithm.md §8, textbook mode) and the physics validation.
inline constexpr double kDefaultFrictionCoefficient = 0.5;

/// Contact model shared by the grasp wrench space (docs/algorithm.md §8) and the physics.
struct ContactModel {
  double mu = kDefaultFrictionCoefficient;  ///< Coulomb friction coefficient [-]
  int cone_edges = 8;                       ///< edges of the linearized friction cone
  /// 0: point contact with friction. > 0: soft finger, torsional friction up to
  /// μ · radius · normal force about the normal (contact patch radius) [m]. Two point contacts
  /// can never be force closure (no moment about the line through them); two soft fingers can.
  double soft_finger_radius_m = 0.0;

  /// Visits every field in declaration order (core/serialize.h).
  template <typename Archive>
  void Serialize(Archive* a) {
    visit_fields(a, CORDGRASP_NVP(mu), CORDGRASP_NVP(cone_edges),
                 CORDGRASP_NVP(soft_finger_radius_m));
  }
};

}  // namespace cordgrasp
