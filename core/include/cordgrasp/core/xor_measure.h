#pragma once
#include <vector>

#include "cordgrasp/core/cord_params.h"
#include "cordgrasp/core/grasp_region.h"
#include "cordgrasp/core/guide_frame.h"

namespace cordgrasp {

/// XOR measure χ, Eq. (1) (docs/algorithm.md §6) [m²]: each front cord i = −n..n (front_cords[n]
/// is the seed's, front_cords.size() = 2n+1) is closed by P_l→P_r, projected orthogonally onto the
/// seed plane `seed_frame`, giving Q_i; χ = (1/2n) Σ_i A(Q_i ⊕ Q_0). Uses params.xor_backend.
/// @throws std::invalid_argument when front_cords.size() is not odd and ≥ 3.
double xor_measure(const std::vector<Polyline3>& front_cords, const PlaneFrame& seed_frame,
                   const CordParams& params = {});

}  // namespace cordgrasp
