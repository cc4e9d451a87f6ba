#pragma once
// Internal to URDF import: where a ROS package named in a package:// mesh URI lives.
#include <map>
#include <string>

namespace cordgrasp::hand_load {

/// Directory of the ROS package `name`, looked up in order: `package_paths` (name → directory,
/// HandLoadOptions::package_paths); each directory D of $ROS_PACKAGE_PATH (colon-separated): D
/// itself when its last component is `name`, else D/name when it holds package.xml; each prefix
/// P of $AMENT_PREFIX_PATH (colon-separated): P/share/name when it is a directory. Returns ""
/// when none matches. Never walks directories (no crawl, no recursion).
std::string find_ros_package(const std::string& name,
                             const std::map<std::string, std::string>& package_paths);

}  // namespace cordgrasp::hand_load
