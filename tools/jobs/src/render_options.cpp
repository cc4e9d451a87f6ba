#include "cordgrasp/jobs/render_options.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <regex>
#include <sstream>

#include "cordgrasp/core/error.h"

namespace cordgrasp {

std::pair<int, int> parse_image_size(const std::string& text) {
  static const std::regex kSize(R"(\s*(\d{1,5})\s*[xX]\s*(\d{1,5})\s*)");
  std::smatch m;
  if (std::regex_match(text, m, kSize)) {
    const int w = std::stoi(m[1]), h = std::stoi(m[2]);
    if (w >= 1 && w <= 8192 && h >= 1 && h <= 8192) return {w, h};
  }
  throw InputError("--size '" + text + "': expected WxH with 1..8192 pixels each, e.g. 1024x768");
}

Eigen::Vector3d parse_vector3(const std::string& text, const std::string& what) {
  std::istringstream in(text);
  Eigen::Vector3d v;
  char sep1 = 0, sep2 = 0;
  if (in >> v.x() >> sep1 >> v.y() >> sep2 >> v.z() && sep1 == ',' && sep2 == ',') {
    in >> std::ws;
    if (in.eof() && v.allFinite()) return v;
  }
  throw InputError(what + " '" + text + "': expected three numbers x,y,z");
}

void check_output_file(const std::string& path) {
  namespace fs = std::filesystem;
  if (path.empty()) throw InputError("output file: empty path");
  std::error_code ec;
  if (fs::is_directory(path, ec))
    throw InputError("'" + path + "': is a directory, cannot write a file there");
  const fs::path dir = fs::path(path).parent_path();
  if (!dir.empty() && !fs::is_directory(dir, ec))
    throw InputError("'" + path + "': output directory does not exist");
  // Writable: create and remove a probe beside the output (access() says yes to root even
  // where a write then fails, e.g. on a read-only mount or in /proc).
  const std::string probe = path + "." + std::to_string(static_cast<long>(::getpid())) + ".probe";
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
  if (fd < 0)
    throw InputError("'" + path + "': cannot write there (" + std::strerror(errno) + ")");
  ::close(fd);
  fs::remove(probe, ec);
}

RenderParams render_params(const PictureOptions& o, Scene& scene,
                           const Eigen::Vector3d& approach_W) {
  RenderParams p;
  std::tie(p.width_px, p.height_px) = parse_image_size(o.size);
  p.supersample = o.supersample;
  p.view.view = parse_view(o.view.empty() ? "iso" : o.view);
  p.view.orthographic = o.orthographic;
  if (p.view.view == View::kApproach) {
    const Eigen::Vector3d d =
        o.approach.empty() ? approach_W : parse_vector3(o.approach, "--approach");
    if (d.norm() == 0.0)
      throw InputError("--view approach needs a direction: give --approach x,y,z");
    p.view.approach_dir_W = d;
  }
  scene.ground = o.ground == "grid"   ? Ground::kGrid
                 : o.ground == "none" ? Ground::kNone
                                      : Ground::kShadow;
  if (!o.caption.empty()) scene.caption = o.caption;
  if (o.no_caption) scene.caption.clear();
  return p;
}

}  // namespace cordgrasp
