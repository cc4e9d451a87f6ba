#pragma once
// The look of a picture as the commands take it (view, size, ground, caption).
#include <Eigen/Core>
#include <string>
#include <utility>

#include "cordgrasp/render/renderer.h"
#include "cordgrasp/render/scene.h"

namespace cordgrasp {

/// Command-line form of a picture's look.
struct PictureOptions {
  std::string view;               ///< iso, front, side, top, approach; empty: the job's default
  std::string approach;           ///< "x,y,z": viewing direction for --view approach
  std::string size = "1024x768";  ///< WxH [px]
  int supersample = 2;            ///< anti-aliasing factor, 1..4
  std::string ground = "shadow";  ///< shadow, grid, none
  std::string caption;            ///< replaces the default caption
  bool no_caption = false;
  bool orthographic = false;
};

/// "1024x768" → (1024, 768). @throws InputError for anything else or sizes outside 1..8192.
std::pair<int, int> parse_image_size(const std::string& text);

/// "x,y,z" → vector. @throws InputError when not three numbers.
Eigen::Vector3d parse_vector3(const std::string& text, const std::string& what);

/// Fails early, before any work, when the output file `path` cannot be written: empty, an
/// existing directory, in a missing directory, or in one where no file can be created.
/// @throws InputError naming the path and the problem.
void check_output_file(const std::string& path);

/// Render parameters from `options`; also applies the ground and caption choices to `scene`.
/// `approach_W` is the default viewing direction of --view approach (e.g. the grasp's approach
/// axis), used when --approach is not given. @throws InputError for bad option values.
RenderParams render_params(const PictureOptions& options, Scene& scene,
                           const Eigen::Vector3d& approach_W = Eigen::Vector3d::Zero());

}  // namespace cordgrasp
