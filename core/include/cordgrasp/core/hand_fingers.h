#pragma once
#include <Eigen/Core>
#include <vector>

#include "cordgrasp/core/hand_model.h"

namespace cordgrasp {

/// One finger: a chain of links that an actor moves, directly or through a coupled (mimic) joint.
/// A parallel gripper's single actor has two fingers; an SAH actor has one.
struct Finger {
  int actor = -1;          ///< index into HandModel::actors
  std::vector<int> links;  ///< the finger's links, root (nearest the palm) first
  bool is_thumb = false;   ///< holds a link of HandModel::thumb_links
  int tip_link = -1;       ///< link carrying the fingertip; -1 when the finger has no geometry
  Eigen::Vector3d p_tip_L = Eigen::Vector3d::Zero();  ///< fingertip in tip_link's frame [m]
};

/// The fingers of `hand`, ordered by actor then root link. The fingertip is the finger's
/// collision-geometry point (geometry_points) farthest from its root joint, in preshape: a point
/// fixed on the finger, to follow as it closes (docs/algorithm.md §7.1 uses thumb and finger
/// tips).
std::vector<Finger> hand_fingers(const HandModel& hand);

}  // namespace cordgrasp
