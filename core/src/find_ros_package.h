#pragma once
// Internal to URDF import: where a ROS package named in a package:// mesh URI lives.
#include <map>
#include <string>

namespace cordgrasp::hand_load {

/// Directory of the ROS package `name`, looked up as rospack and ament do, in order:
/// `package_paths` (name → directory, HandLoadOptions::package_paths); the packages crawled
/// under $ROS_PACKAGE_PATH (crawl_ros_packages: package.xml <name>, first directory wins); each
/// prefix P of $AMENT_PREFIX_PATH (colon-separated): P/share/name when
/// P/share/ament_index/resource_index/packages/name or P/share/name/package.xml exists.
/// Returns "" when none matches.
std::string find_ros_package(const std::string& name,
                             const std::map<std::string, std::string>& package_paths);

/// The places find_ros_package searched, for an error message: "package_paths {a, b},
/// ROS_PACKAGE_PATH '/ws/src' (3 package.xml), AMENT_PREFIX_PATH unset".
std::string ros_package_search_summary(const std::map<std::string, std::string>& package_paths);

}  // namespace cordgrasp::hand_load
