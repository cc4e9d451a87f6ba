#pragma once
#include <cstdint>

#include "cordgrasp/core/grasp.h"
#include "cordgrasp/core/serialize.h"

namespace cordgrasp {

/// How far a grasp is jittered for a repeated physics trial (docs/physics.md: held / not-held
/// of marginal grasps is chaotic, so one run is a sample, not a verdict).
struct PerturbationParams {
  double offset_m = 1e-4;   ///< the hand is moved by exactly this far, in a random direction
  double turn_rad = 1e-3;   ///< and turned by exactly this much, about a random axis through the GCP

  /// Visits every field in declaration order (core/serialize.h).
  template <typename Archive>
  void Serialize(Archive* a) {
    visit_fields(a, CORDGRASP_NVP(offset_m), CORDGRASP_NVP(turn_rad));
  }
};

/// `grasp` with its hand (root and GCP, preshape and joints unchanged) moved and turned
/// relative to the object as PerturbationParams says; directions drawn from `seed` alone.
Grasp perturbed_grasp(const Grasp& grasp, const PerturbationParams& params, std::uint64_t seed);

}  // namespace cordgrasp
