#pragma once
// A plan's grasps as moveit_msgs/Grasp messages in YAML; conventions in docs/export.md.
#include <string>
#include <vector>

#include "cordgrasp/core/grasp.h"
#include "cordgrasp/core/hand_model.h"

namespace cordgrasp {

/// Settings of the moveit_msgs/Grasp messages.
struct MoveitGraspParams {
  std::string object_frame = "object";   ///< grasp_pose.header.frame_id
  double approach_desired_m = 0.10;      ///< pre_grasp_approach.desired_distance [m]
  double approach_min_m = 0.05;          ///< pre_grasp_approach.min_distance [m]
  double retreat_desired_m = 0.10;       ///< post_grasp_retreat.desired_distance [m]
  double retreat_min_m = 0.05;           ///< post_grasp_retreat.min_distance [m]
  double posture_time_s = 1.0;           ///< time_from_start of the one posture point [s]
  std::string id_prefix = "grasp_";      ///< id of grasp k: prefix + k
};

/// YAML list of one moveit_msgs/Grasp per grasp: grasp_pose = the root link in the object
/// frame, pre_grasp_posture = preshape, grasp_posture = joints after closing (every moving
/// joint), approach along the GCP's +z in the root link frame, retreat the reverse,
/// grasp_quality = ε.
std::string moveit_grasps_yaml(const HandModel& hand, const std::vector<Grasp>& grasps,
                               const MoveitGraspParams& params = {});

}  // namespace cordgrasp
