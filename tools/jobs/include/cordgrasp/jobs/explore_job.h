#pragma once
// `cordgrasp explore` as a job: the cord exploration alone on one object, for a hand's palm
// width or an explicit one, optionally written as JSON (the regions `render --regions` draws).
#include <cstdint>
#include <string>
#include <vector>

#include "cordgrasp/core/cord_params.h"
#include "cordgrasp/core/explore_cords.h"
#include "cordgrasp/core/grasp_region.h"

namespace cordgrasp {

/// Inputs and settings of explore_job().
struct ExploreJobParams {
  std::string object;
  std::string units = "m";
  std::string hand;  // empty: the shipped default hand (unless --palm-width-m)
  double palm_width_m = 0.0;
  int sets = 20;
  std::uint64_t seed = 1;
  bool no_local_improvement = false;
  std::string side_cords = "empty";
  std::string xor_backend = "convex";
  double time_limit_s = 30.0;
  int top = 20;
  std::string json_path;
};

/// What explore_job() found.
struct ExploreOutcome {
  std::string object_name;
  int triangles = 0;
  double palm_width_m = 0.0;
  std::string palm_width_from;  ///< "hand NAME" or "--palm-width-m"
  CordParams params;            ///< the exploration's parameters
  ExplorationStats stats;
  std::vector<GraspRegion> regions;  ///< best (lowest χ) first
};

/// Explores `p.object`; writes p.json_path when set. @throws InputError for bad inputs.
ExploreOutcome explore_job(const ExploreJobParams& p);

}  // namespace cordgrasp
