#pragma once
// JSON form of a grasp region (cord planner exploration result), for plan.json: lets `render`
// draw a grasp's cords and P1, P_l, P_r without re-running the exploration.
//
// Layout (object frame, meters), as the regions of `cordgrasp explore --json`:
//   {p1, p2, p3, normal, p_l, p_r, p_m: [x, y, z], case: "I" | "II", n,
//    front_cords: [[[x, y, z], ...], ...] (2n + 1 polylines, i = −n..n), xi_m, chi_m2,
//    from_local_improvement}
#include <nlohmann/json.hpp>

#include "cordgrasp/core/grasp_region.h"

namespace cordgrasp {

/// JSON of `region` (layout above).
nlohmann::json region_to_json(const GraspRegion& region);

/// Region from region_to_json() output. @throws InputError naming the missing or malformed
/// field (front_cords must hold 2n + 1 polylines).
GraspRegion region_from_json(const nlohmann::json& j);

}  // namespace cordgrasp
