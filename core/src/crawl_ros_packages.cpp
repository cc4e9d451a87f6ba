#include "crawl_ros_packages.h"

#include <tinyxml.h>

#include <algorithm>
#include <filesystem>
#include <mutex>
#include <set>
#include <utility>
#include <vector>

namespace fs = std::filesystem;

namespace cordgrasp::hand_load {
namespace {

bool path_exists(const fs::path& p) {
  std::error_code ec;
  return fs::exists(p, ec);
}

bool is_dir(const fs::path& p) {
  std::error_code ec;
  return fs::is_directory(p, ec);
}

bool is_file(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

/// The build tools' markers of a directory tree to leave out (catkin, ament, colcon).
bool is_ignored(const fs::path& dir) {
  for (const char* marker : {"CATKIN_IGNORE", "AMENT_IGNORE", "COLCON_IGNORE"})
    if (path_exists(dir / marker)) return true;
  return false;
}

/// Subdirectories of `dir` that are not hidden, in name order (symlinks to directories count).
std::vector<fs::path> subdirectories(const fs::path& dir) {
  std::vector<fs::path> out;
  std::error_code ec;
  fs::directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec);
  for (; !ec && it != fs::directory_iterator(); it.increment(ec)) {
    const fs::path& p = it->path();
    const std::string name = p.filename().string();
    if (name.empty() || name[0] == '.') continue;
    if (is_dir(p)) out.push_back(p);
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// Adds the packages under `root` to `index` (names already there are kept).
void crawl(const fs::path& root, RosPackageIndex& index) {
  std::set<fs::path> walked;  // canonical paths: a symlink loop or a second link is walked once
  std::vector<std::pair<fs::path, int>> stack{{root, 0}};  // (directory, depth below root)
  while (!stack.empty()) {
    const auto [dir, depth] = stack.back();
    stack.pop_back();
    if (depth > kMaxCrawlDepth || !is_dir(dir) || is_ignored(dir)) continue;
    std::error_code ec;
    const fs::path canonical = fs::canonical(dir, ec);
    if (ec || !walked.insert(canonical).second) continue;
    if (const fs::path xml = dir / "package.xml"; is_file(xml)) {
      ++index.package_xml_count;
      const std::string name = read_package_name(xml.string());
      if (!name.empty()) index.dirs.emplace(name, dir.lexically_normal().string());
      continue;  // a package ends the walk: packages inside packages are not packages
    }
    const std::vector<fs::path> children = subdirectories(dir);
    for (auto it = children.rbegin(); it != children.rend(); ++it)  // first name on top
      stack.emplace_back(*it, depth + 1);
  }
}

}  // namespace

std::string read_package_name(const std::string& path) {
  TiXmlDocument doc;
  if (!doc.LoadFile(path)) return "";
  const TiXmlElement* root = doc.RootElement();
  if (!root || root->ValueStr() != "package") return "";
  const TiXmlElement* name = root->FirstChildElement("name");
  if (!name || !name->GetText()) return "";
  const std::string text = name->GetText();
  const char* kSpace = " \t\r\n";
  const size_t begin = text.find_first_not_of(kSpace);
  if (begin == std::string::npos) return "";
  return text.substr(begin, text.find_last_not_of(kSpace) - begin + 1);
}

std::shared_ptr<const RosPackageIndex> crawl_ros_packages(const std::string& ros_package_path) {
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<const RosPackageIndex>> cache;
  std::lock_guard<std::mutex> lock(mutex);  // held while crawling: one walk per value
  if (const auto it = cache.find(ros_package_path); it != cache.end()) return it->second;
  auto index = std::make_shared<RosPackageIndex>();
  size_t begin = 0;
  while (begin <= ros_package_path.size()) {
    size_t end = ros_package_path.find(':', begin);
    if (end == std::string::npos) end = ros_package_path.size();
    if (end > begin) crawl(ros_package_path.substr(begin, end - begin), *index);
    begin = end + 1;
  }
  cache.emplace(ros_package_path, index);
  return index;
}

}  // namespace cordgrasp::hand_load
