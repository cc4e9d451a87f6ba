#include "find_ros_package.h"

#include <cstdlib>
#include <filesystem>
#include <vector>

#include "crawl_ros_packages.h"

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

bool file_exists(const fs::path& p) {
  std::error_code ec;
  return fs::exists(p, ec) && !fs::is_directory(p, ec);
}

}  // namespace

std::string find_ros_package(const std::string& name,
                             const std::map<std::string, std::string>& package_paths) {
  if (name.empty()) return "";
  if (const auto it = package_paths.find(name); it != package_paths.end()) return it->second;
  if (const char* ros = std::getenv("ROS_PACKAGE_PATH")) {
    const auto index = crawl_ros_packages(ros);
    if (const auto it = index->dirs.find(name); it != index->dirs.end()) return it->second;
  }
  for (const fs::path& prefix : env_path_list("AMENT_PREFIX_PATH")) {
    const fs::path share = prefix / "share";
    if (file_exists(share / "ament_index" / "resource_index" / "packages" / name) ||
        file_exists(share / name / "package.xml"))
      return (share / name).string();
  }
  return "";
}

std::string ros_package_search_summary(const std::map<std::string, std::string>& package_paths) {
  std::string out = "package_paths {";
  for (auto it = package_paths.begin(); it != package_paths.end(); ++it)
    out += (it == package_paths.begin() ? "" : ", ") + it->first;
  out += "}, ROS_PACKAGE_PATH ";
  if (const char* ros = std::getenv("ROS_PACKAGE_PATH"))
    out += "'" + std::string(ros) + "' (" +
           std::to_string(crawl_ros_packages(ros)->package_xml_count) + " package.xml)";
  else
    out += "unset";
  out += ", AMENT_PREFIX_PATH ";
  if (const char* ament = std::getenv("AMENT_PREFIX_PATH"))
    out += "'" + std::string(ament) + "'";
  else
    out += "unset";
  return out;
}

}  // namespace cordgrasp::hand_load
