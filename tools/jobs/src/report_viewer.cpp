#include "cordgrasp/jobs/report_viewer.h"

#include <filesystem>
#include <fstream>
#include <iterator>

#include "cordgrasp/core/atomic_file.h"
#include "cordgrasp/core/error.h"
#include "cordgrasp/jobs/export_mesh.h"

namespace cordgrasp {
namespace {

namespace fs = std::filesystem;

/// The bytes of `path`. @throws InputError naming it, what it is and `hint` when unreadable.
std::string read_bytes(const std::string& path, const std::string& what,
                       const std::string& hint = "") {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("report viewer: " + what + " '" + path + "' is missing" + hint);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

constexpr const char* kThreeHint = " (Debian package libjs-three; tools/install-deps.sh)";

std::string base64(const std::string& bytes) {
  static constexpr char kDigits[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const size_t n = std::min<size_t>(3, bytes.size() - i);
    unsigned v = 0;
    for (size_t k = 0; k < 3; ++k)
      v = (v << 8) | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
    for (size_t k = 0; k < 4; ++k) out += k <= n ? kDigits[(v >> (18 - 6 * k)) & 63u] : '=';
  }
  return out;
}

}  // namespace

ViewerSources default_viewer_sources() {
  ViewerSources s;
  const fs::path dir = CORDGRASP_THREE_DIR;
  s.three_js = (dir / "build" / "three.min.js").string();
  s.gltf_loader_js = (dir / "examples" / "js" / "loaders" / "GLTFLoader.js").string();
  s.orbit_controls_js = (dir / "examples" / "js" / "controls" / "OrbitControls.js").string();
  s.licence = CORDGRASP_THREE_LICENCE;
  return s;
}

void write_viewer_scripts(const std::string& out_dir, const ViewerSources& sources) {
  // Read all before writing any: a missing file leaves no partial viewer folder.
  const std::string three = read_bytes(sources.three_js, "three.js", kThreeHint);
  const std::string loader = read_bytes(sources.gltf_loader_js, "three.js GLTFLoader", kThreeHint);
  const std::string controls =
      read_bytes(sources.orbit_controls_js, "three.js OrbitControls", kThreeHint);
  const std::string licence = read_bytes(sources.licence, "three.js licence", kThreeHint);
  const fs::path dir = fs::path(out_dir) / kViewerDir;
  fs::create_directories(dir);
  write_file_atomically((dir / "three.min.js").string(), three);
  write_file_atomically((dir / "GLTFLoader.js").string(), loader);
  write_file_atomically((dir / "OrbitControls.js").string(), controls);
  write_file_atomically((dir / "copyright").string(), licence);
}

void write_grasp_model_script(const std::string& out_dir, const std::string& name,
                              const HandModel& hand, const Grasp& grasp, const Mesh& object) {
  const fs::path glb = fs::path(out_dir) / (name + ".glb");
  // assimp writes in place: through a scratch file, so that the .glb appears whole.
  const fs::path scratch = fs::path(out_dir) / ("." + name + ".glb.part");
  write_grasp_mesh(scratch.string(), "glb2", hand, grasp, object);
  const std::string bytes = read_bytes(scratch.string(), "glTF binary");
  fs::remove(scratch);
  write_file_atomically(glb.string(), bytes);
  write_file_atomically((fs::path(out_dir) / (name + ".glb.js")).string(),
                        "// " + name +
                            ".glb (the posed hand and the object) for report.html\n"
                            "window.cordgraspModels = window.cordgraspModels || {};\n"
                            "window.cordgraspModels[\"" +
                            name + "\"] = \"" + base64(bytes) + "\";\n");
}

}  // namespace cordgrasp
