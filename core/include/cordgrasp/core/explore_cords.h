#pragma once
#include <memory>
#include <vector>

#include "cordgrasp/core/cord_params.h"
#include "cordgrasp/core/grasp_region.h"
#include "cordgrasp/core/mesh.h"
#include "cordgrasp/core/mesh_bvh.h"

namespace cordgrasp {

/// Counters and timings of one explore_cords() run.
struct ExplorationStats {
  long long triangles_sampled = 0;  ///< guide triangles drawn by Algorithm 1
  long long triangles_acute = 0;    ///< of those, acute
  long long seed_cords = 0;         ///< acute ones whose seed front cord was built
  long long sets_tried = 0;         ///< eligible seeds that were scanned
  long long sets_valid = 0;         ///< fully scanned sets from sampling
  long long improvement_tried = 0;  ///< local-improvement perturbations drawn
  long long improvement_valid = 0;  ///< valid sets they produced
  int iterations = 0;               ///< outer iterations (reshuffles) started, ≤ M
  double sampling_time_s = 0.0;     ///< wall clock of Algorithm 1 [s]
  double improvement_time_s = 0.0;  ///< wall clock of local improvement [s]
  double time_s = 0.0;              ///< total wall clock, including setup [s]
  bool hit_time_limit = false;      ///< the time cap stopped the run (result not reproducible)
};

/// Exploration stage (docs/algorithm.md §5): Algorithm 1 samples guide triangles (P1 on s1, P2, P3
/// on s2, shuffled sphere sequences, acute only) until params.sets valid scanned sets exist or the
/// iteration/time cap is hit, then local improvement; returns every valid set ranked by ascending
/// χ (ties keep discovery order). Same params (seed) → identical regions, unless the time cap is
/// hit. `palm_width_m` is W_palm (docs/algorithm.md §4) [m].
/// `object_bvh`: the mesh's build_object_bvh when one exists (the collider's), else built.
/// `threads`: sampled guide triangles (a few at a time) and local improvement's perturbations
/// are scanned on this many threads; the regions and counters do not depend on it.
/// @throws std::invalid_argument for an empty mesh or palm_width_m ≤ 0.
std::vector<GraspRegion> explore_cords(const Mesh& mesh, double palm_width_m,
                                       const CordParams& params = {},
                                       ExplorationStats* stats = nullptr,
                                       std::shared_ptr<const MeshBvh> object_bvh = nullptr,
                                       int threads = 1);

}  // namespace cordgrasp
