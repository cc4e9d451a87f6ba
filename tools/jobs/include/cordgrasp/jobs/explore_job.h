#pragma once
// `cordgrasp explore` as a job: the cord exploration alone on one object, for a hand's palm
// width or an explicit one, optionally written as JSON (the regions `render --regions` draws).
#include <cstdint>
#include <string>
#include <vector>

#include "cordgrasp/core/cord_params.h"
#include "cordgrasp/core/explore_cords.h"
#include "cordgrasp/core/grasp_region.h"
#include "cordgrasp/core/hand_description.h"
#include "cordgrasp/core/mesh_io.h"

namespace cordgrasp {

/// Inputs and settings of explore_job().
struct ExploreJobParams {
  std::string object;                         ///< mesh file
  LengthUnits units = LengthUnits::kMeters;   ///< units of the mesh file
  double scale = 1.0;                         ///< uniform scale after the units
  std::string hand;          ///< palm width from this hand ("": the shipped default hand)
  HandLoadOptions hand_load; ///< package:// directories of the hand's URDF
  double palm_width_m = 0.0; ///< > 0: this palm width instead of a hand's [m]
  CordParams cord;           ///< every exploration parameter
  int top = 20;              ///< regions the command prints (0 = all)
  std::string json_path;     ///< also write the regions and stats here ("" = no)
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
