#pragma once
// Picture options shared by the commands that render (render, later validate --snapshots).
#include <CLI/CLI.hpp>
#include <Eigen/Core>
#include <string>
#include <utility>

#include "cordgrasp/render/renderer.h"
#include "cordgrasp/render/scene.h"

namespace cordgrasp::cli {

/// Command-line form of a picture's look.
struct PictureOptions {
  std::string view = "iso";       ///< iso, front, side, top, approach
  std::string approach;           ///< "x,y,z": viewing direction for --view approach
  std::string size = "1024x768";  ///< WxH [px]
  int supersample = 2;            ///< anti-aliasing factor, 1..4
  std::string ground = "shadow";  ///< shadow, grid, none
  std::string caption;            ///< replaces the default caption
  bool no_caption = false;
  bool orthographic = false;
  const CLI::Option* view_option = nullptr;  ///< set by add_picture_options: was --view given?

  /// True when --view was given on the command line.
  bool view_given() const { return view_option && view_option->count() > 0; }
};

/// Adds --view, --approach, --size, --supersample, --ground, --caption, --no-caption, --ortho.
void add_picture_options(CLI::App& cmd, PictureOptions& options);

/// "1024x768" → (1024, 768). @throws InputError for anything else or sizes outside 1..8192.
std::pair<int, int> parse_image_size(const std::string& text);

/// "x,y,z" → vector. @throws InputError when not three numbers.
Eigen::Vector3d parse_vector3(const std::string& text, const std::string& what);

/// Fails early, before rendering, when the directory of the output file `path` does not exist.
/// @throws InputError naming the path.
void check_output_file(const std::string& path);

/// Render parameters from `options`; also applies the ground and caption choices to `scene`.
/// `approach_W` is the default viewing direction of --view approach (e.g. the grasp's approach
/// axis), used when --approach is not given. @throws InputError for bad option values.
RenderParams render_params(const PictureOptions& options, Scene& scene,
                           const Eigen::Vector3d& approach_W = Eigen::Vector3d::Zero());

}  // namespace cordgrasp::cli
