#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace cordgrasp {

/// Triangle soup in meters (docs/algorithm.md §1): no manifoldness, closure or consistent
/// orientation is assumed. Coordinates are in the object's own frame, as authored.
struct Mesh {
  std::vector<Eigen::Vector3d> vertices;   ///< [m]
  std::vector<Eigen::Vector3i> triangles;  ///< indices into `vertices`, orientation unreliable
  std::string name;                        ///< file stem or generator name, for messages
};

}  // namespace cordgrasp
