// Where the shipped hands and objects live, and --hand / --object text resolved to files.
#include "cordgrasp/core/assets.h"

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include "cordgrasp/core/error.h"
#include "cordgrasp/core/object_meshes.h"

namespace fs = std::filesystem;

namespace cordgrasp {
namespace {

std::string quoted(const std::string& s) { return "'" + s + "'"; }

// The folder of the file holding this code: the program, or the shared object (the Python
// module) it is linked into; empty when unknown.
fs::path code_dir() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&code_dir), &info) && info.dli_fname &&
      *info.dli_fname) {
    std::error_code ec;
    const fs::path file = fs::canonical(info.dli_fname, ec);
    if (!ec) return file.parent_path();
  }
  return {};
}

fs::path program_dir() {
  std::error_code ec;
  const fs::path exe = fs::canonical("/proc/self/exe", ec);
  return ec ? fs::path() : exe.parent_path();
}

bool holds_assets(const fs::path& dir) {
  std::error_code ec;
  return !dir.empty() && fs::is_directory(dir / "hands", ec);
}

bool inside(const fs::path& dir, const fs::path& root) {
  if (dir.empty()) return false;
  const std::string d = (dir / "").string(), r = (fs::path(root) / "").string();
  return d.compare(0, r.size(), r) == 0;
}

// share/cordgrasp of an installation holding the running program or module: each compiled-in
// relative path (bin -> share, lib -> share, Python package -> share) from both folders.
std::string installed_assets_dir() {
  const std::string relative = CORDGRASP_ASSETS_RELATIVE_DIRS;  // "a:b:c"
  for (const fs::path& base : {code_dir(), program_dir()}) {
    if (base.empty()) continue;
    size_t start = 0;
    while (start <= relative.size()) {
      const size_t end = std::min(relative.find(':', start), relative.size());
      const fs::path candidate = (base / relative.substr(start, end - start)).lexically_normal();
      if (end > start && holds_assets(candidate)) return candidate.string();
      start = end + 1;
    }
  }
  return {};
}

}  // namespace

std::string assets_dir() {
  const char* env = std::getenv("CORDGRASP_ASSETS_DIR");
  if (env && *env) return env;
  static const std::string found = [] {
    const std::string source = CORDGRASP_SOURCE_ASSETS_DIR;
    const std::string prefix = CORDGRASP_INSTALL_ASSETS_DIR;
    const fs::path build_dir = CORDGRASP_BUILD_DIR;
    const bool in_build = inside(code_dir(), build_dir) || inside(program_dir(), build_dir);
    if (in_build && holds_assets(source)) return source;
    const std::string installed = installed_assets_dir();
    if (!installed.empty()) return installed;
    if (holds_assets(prefix)) return prefix;
    return holds_assets(source) ? source : prefix;
  }();
  return found;
}

std::string shipped_objects_dir() { return (fs::path(assets_dir()) / "objects").string(); }

std::string resolve_object_path(const std::string& name_or_path) {
  if (name_or_path.empty()) throw InputError("--object: empty object name");
  if (fs::exists(fs::path(name_or_path))) return name_or_path;
  const fs::path shipped = fs::path(shipped_objects_dir()) / (name_or_path + ".obj");
  if (name_or_path.find('/') == std::string::npos && fs::is_regular_file(shipped))
    return shipped.lexically_normal().string();
  std::string names;
  for (const std::string& n : shipped_object_names()) names += (names.empty() ? "" : ", ") + n;
  throw InputError("--object '" + name_or_path + "': no such file, nor a shipped object (" +
                   names + ")");
}

std::string shipped_hands_dir() { return (fs::path(assets_dir()) / "hands").string(); }

const char* default_hand_name() { return "cordgrasp_sah"; }

std::string resolve_hand_path(const std::string& name_or_path) {
  if (name_or_path.empty()) throw InputError("--hand: empty hand name");
  const fs::path given(name_or_path);
  if (fs::is_regular_file(given)) {
    const std::string ext = given.extension().string();
    if (ext == ".urdf" || ext == ".URDF" || ext == ".xml")
      throw InputError("--hand " + quoted(name_or_path) +
                       ": this is a URDF; pass the hand description (YAML) that names it");
    return given.string();
  }
  if (fs::is_directory(given)) {  // a hand folder: <dir>/<dir name>.yaml
    const fs::path inside = given / (given.lexically_normal().filename().string() + ".yaml");
    if (fs::is_regular_file(inside)) return inside.string();
  }
  const fs::path dir = shipped_hands_dir();
  for (const fs::path& p :
       {dir / (name_or_path + ".yaml"), dir / name_or_path / (name_or_path + ".yaml")})
    if (fs::is_regular_file(p)) return p.lexically_normal().string();
  std::vector<std::string> names;
  if (fs::is_directory(dir))
    for (const auto& e : fs::directory_iterator(dir)) {
      if (e.path().extension() == ".yaml") names.push_back(e.path().stem().string());
      if (e.is_directory() &&
          fs::is_regular_file(e.path() / (e.path().filename().string() + ".yaml")))
        names.push_back(e.path().filename().string());
    }
  std::sort(names.begin(), names.end());
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  throw InputError("--hand " + quoted(name_or_path) +
                   ": no such description file and no shipped hand of that name (shipped in " +
                   quoted(dir.string()) + ": " + (list.empty() ? "none" : list) + ")");
}

}  // namespace cordgrasp
