#include "cordgrasp/core/assets.h"

#include <cstdlib>
#include <filesystem>

#include "cordgrasp/core/error.h"
#include "cordgrasp/core/object_meshes.h"

namespace fs = std::filesystem;

namespace cordgrasp {

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

}  // namespace cordgrasp
