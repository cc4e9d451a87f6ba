#pragma once
#include <Eigen/Core>
#include <vector>

#include "cordgrasp/core/finger_stage.h"
#include "cordgrasp/core/grasp.h"

namespace cordgrasp {

/// CandidateMeasures of `contacts` for the hand of `setup` (actor and static links), the
/// object's centre of mass `com_O` and bounding radius `radius_m` (> 0).
CandidateMeasures candidate_measures(const std::vector<Contact>& contacts,
                                     const HandSetup& setup, const Eigen::Vector3d& com_O,
                                     double radius_m);

}  // namespace cordgrasp
