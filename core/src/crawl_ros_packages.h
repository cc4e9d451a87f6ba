#pragma once
// Internal to URDF import: the ROS packages under the directories of $ROS_PACKAGE_PATH, found as
// rospack and catkin find them (a crawl for package.xml files, named by their <name>).
#include <map>
#include <memory>
#include <string>

namespace cordgrasp::hand_load {

/// Deepest directory level below a ROS_PACKAGE_PATH directory that the crawl enters (rospack's
/// MAX_CRAWL_DEPTH).
constexpr int kMaxCrawlDepth = 1000;

/// ROS packages of one ROS_PACKAGE_PATH value: package name (package.xml <name>) → directory.
struct RosPackageIndex {
  std::map<std::string, std::string> dirs;  ///< name → package directory; first found wins
  int package_xml_count = 0;                ///< package.xml files met, named or not
};

/// The packages under each directory of `ros_package_path` (colon-separated; the first
/// directory listing a name wins). Each is walked depth first, subdirectories in name order: a
/// directory holding package.xml is a package named by its <name> element and is not descended
/// into (nested packages are not found); a directory holding CATKIN_IGNORE, AMENT_IGNORE or
/// COLCON_IGNORE is skipped whole, as are hidden directories, directories deeper than
/// kMaxCrawlDepth and directories already walked (symlinks are followed; loops end). Missing or
/// unreadable directories and package.xml files without a <name> are skipped. Cached for the
/// process per value of `ros_package_path` (thread-safe): a later call does not walk again.
std::shared_ptr<const RosPackageIndex> crawl_ros_packages(const std::string& ros_package_path);

/// The <name> element of package.xml at `path` (read with TinyXML, whitespace trimmed); ""
/// when the file does not parse, its root is not <package> or it has no <name>.
std::string read_package_name(const std::string& path);

}  // namespace cordgrasp::hand_load
