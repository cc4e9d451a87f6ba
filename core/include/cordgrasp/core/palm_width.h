#pragma once
#include "cordgrasp/core/hand_model.h"

namespace cordgrasp {

/// W_palm measured on the hand in preshape (docs/algorithm.md §4) [m]: the extent, along the
/// hand's lateral (finger-spread) axis l = z_GCP × o, of the collision geometry of every non-thumb
/// finger (hand_fingers), i.e. the lateral span between the outer fingers' centre lines plus one
/// finger width. o is the opposition direction of docs/algorithm.md §7.1: from the thumb tip to
/// the centroid of the other fingertips, projected onto the GCP xy-plane (GCP x when no finger is
/// a thumb). With only thumb fingers, all fingers are measured.
/// @throws std::invalid_argument when no actor moves collision geometry.
double measure_palm_width(const HandModel& hand);

/// W_palm for the planner [m]: the description's palm_width_m when given, else
/// measure_palm_width(hand).
double palm_width(const HandModel& hand);

}  // namespace cordgrasp
