#pragma once
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "cordgrasp/core/mesh_bvh.h"

namespace cordgrasp {

/// Resolution of the sampled cord (docs/algorithm.md §2.4).
struct SampledTightenOptions {
  double step_m = 1e-3;    ///< march step Δu = min(step_m, L/1000) along the guide [m]
  double bisect_m = 1e-6;  ///< bisect until ‖G(u_hi) − G(u_lo)‖ < this [m] (tests: 1e-12)
  double self_m = 1e-7;    ///< ε_self: hits this close to the ray origin or target are ignored [m]
};

/// Reference cord by sampled 3D ray casting (docs/algorithm.md §2.4, after Coleman & Singh): march
/// the target along the guide by arc length, cast segment anchor→target with Primitive B, bisect
/// the first blocked step, take the first hit of the blocked ray as the grazing point (new
/// anchor), continue from u_lo; append the guide's end. A ray between two surface points can cross
/// the interior without a hit, so the march stops 1 µm before an end point that may lie on the
/// surface (P_l). Anchors and targets must not lie inside the object. For tests only: converges to
/// tighten_cord (docs/algorithm.md §2.3). Returns nullopt when the march stalls (> 100000 events).
std::optional<std::vector<Eigen::Vector3d>> tighten_cord_sampled(
    const MeshBvh& bvh, const std::vector<Eigen::Vector3d>& guide,
    const SampledTightenOptions& options = {});

}  // namespace cordgrasp
