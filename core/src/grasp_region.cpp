#include "cordgrasp/core/grasp_region.h"

#include <algorithm>

namespace cordgrasp {

int side_cords_missed(const GraspRegion& region) {
  return static_cast<int>(std::count_if(region.front_cords.begin(), region.front_cords.end(),
                                        [](const Polyline3& cord) { return cord.empty(); }));
}

}  // namespace cordgrasp
