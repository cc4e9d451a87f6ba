#include "find_ros_package.h"

#include <cstdlib>
#include <filesystem>
#include <vector>

namespace fs = std::filesystem;

namespace cordgrasp::hand_load {
namespace {

/// Non-empty entries of a colon-separated environment variable (none when unset).
std::vector<fs::path> env_path_list(const char* variable) {
  std::vector<fs::path> out;
  const char* value = std::getenv(variable);
  if (!value) return out;
  const std::string text(value);
  size_t begin = 0;
  while (begin <= text.size()) {
    size_t end = text.find(':', begin);
    if (end == std::string::npos) end = text.size();
    if (end > begin) out.emplace_back(text.substr(begin, end - begin));
    begin = end + 1;
  }
  return out;
}

bool directory_exists(const fs::path& p) {
  std::error_code ec;
  return fs::is_directory(p, ec);
}

bool file_exists(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

}  // namespace

std::string find_ros_package(const std::string& name,
                             const std::map<std::string, std::string>& package_paths) {
  if (name.empty()) return "";
  if (const auto it = package_paths.find(name); it != package_paths.end()) return it->second;
  for (const fs::path& dir : env_path_list("ROS_PACKAGE_PATH")) {
    const fs::path normal = dir.lexically_normal();  // "a/b/" keeps its trailing separator
    const fs::path last =
        normal.has_filename() ? normal.filename() : normal.parent_path().filename();
    if (last == name && directory_exists(dir)) return dir.string();
    if (file_exists(dir / name / "package.xml")) return (dir / name).string();
  }
  for (const fs::path& prefix : env_path_list("AMENT_PREFIX_PATH")) {
    const fs::path share = prefix / "share" / name;
    if (directory_exists(share)) return share.string();
  }
  return "";
}

}  // namespace cordgrasp::hand_load
