// Where the shipped hands and objects live, and --hand / --object text resolved to files.
#include "cordgrasp/core/assets.h"

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

}  // namespace

std::string assets_dir() {
  const char* env = std::getenv("CORDGRASP_ASSETS_DIR");
  if (env && *env) return env;
  return CORDGRASP_ASSETS_DIR;
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
