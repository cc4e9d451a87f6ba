#pragma once
#include <Eigen/Core>
#include <vector>

#include "cordgrasp/core/cord_params.h"

namespace cordgrasp {

/// `count` deterministic near-uniform points on the unit sphere (docs/algorithm.md §5).
/// kYershovaLaValle: the Lindemann–LaValle incremental lattice (index i = 1, 2, …; base-4
/// digits, least significant first, digit d at depth k adds 2^−k·L[d]) mapped onto the 6 cube
/// faces in turn by spherical bilinear interpolation (slerp along two opposite face edges,
/// then between them). kFibonacci: golden-angle spiral with z = 1 − (2i+1)/count.
/// @throws std::invalid_argument when count < 0.
std::vector<Eigen::Vector3d> sphere_points(int count, SphereSequence kind);

}  // namespace cordgrasp
