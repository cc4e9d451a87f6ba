#pragma once
// core-internal: segment–mesh hits for the finger stage and the generic planner (spec §2.3,
// Primitive B): two-sided Möller–Trumbore, brute force over the soup.
#include <Eigen/Core>
#include <vector>

#include "cordgrasp/core/mesh.h"

namespace cordgrasp::internal {

/// Parameters t ∈ [0, 1] of the hits of segment a→b with the soup, sorted, hits closer than
/// 1e-9 m merged (edge and vertex hits appear once).
std::vector<double> segment_hit_params(const Mesh& mesh, const Eigen::Vector3d& a,
                                       const Eigen::Vector3d& b);

}  // namespace cordgrasp::internal
