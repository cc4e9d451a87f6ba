#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cordgrasp/render/camera.h"
#include "cordgrasp/render/image.h"
#include "cordgrasp/render/scene.h"

namespace cordgrasp {

/// Options of one picture.
struct RenderParams {
  int width_px = 1024;  ///< output width [px]
  int height_px = 768;  ///< output height [px], caption band included
  int supersample = 2;  ///< anti-aliasing: render at this factor, box-filter down (1 = off)
  ViewSpec view;        ///< auto-framing on the scene bounds (ignored when `camera` is set)
  std::optional<Camera> camera;  ///< explicit camera instead of auto-framing
  Rgba background = Rgba(1.0, 1.0, 1.0, 1.0);
  double crease_angle_rad = 0.6981317007977318;  ///< smooth shading splits sharper edges (40°)
  double caption_size_px = 0.0;   ///< caption font size [px]; 0: height/36, at least 11
  double shadow_strength = 0.45;  ///< Ground::kShadow darkness under contact, in [0, 1]
};

/// Where the 3D view went in a rendered image: the top `view_height_px` rows; the caption
/// band (if any) fills the rest.
struct RenderInfo {
  Camera camera;           ///< the camera used (auto-framed or given)
  int view_width_px = 0;   ///< [px]
  int view_height_px = 0;  ///< [px]
  bool caption_drawn = false;
  int dropped_items = 0;    ///< scene items left out for non-finite coordinates
};

/// Offscreen OpenGL renderer (OSMesa, software). Owns one GL context; keeps GPU copies of the
/// meshes it has drawn while their shared_ptrs live, so rendering frames of the same meshes
/// repeatedly is cheap. Not thread-safe: use one Renderer per thread.
class Renderer {
 public:
  /// Creates the OSMesa context. @throws std::runtime_error when OSMesa cannot create it.
  Renderer();
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  /// Renders `scene`; fills `info` if given. Same scene and params give identical bytes.
  /// Items with non-finite coordinates are left out (counted in RenderInfo::dropped_items).
  /// @throws std::invalid_argument for sizes outside [1, 8192] px or supersample outside [1, 4].
  Image render(const Scene& scene, const RenderParams& params, RenderInfo* info = nullptr);

  /// "OpenGL <version> (<profile>), <renderer>" of this context, e.g. llvmpipe.
  std::string gl_description() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The camera render() would auto-frame for all `scenes` together (union of their extents,
/// floor at the lowest floor), for the image layout of the first scene (caption band). Pass it
/// as RenderParams::camera to show a series of frames from one viewpoint.
/// @throws std::invalid_argument when `scenes` is empty.
Camera frame_scenes(const std::vector<Scene>& scenes, const RenderParams& params);

/// One-shot convenience: a fresh Renderer renders `scene`.
Image render_scene(const Scene& scene, const RenderParams& params = {});

}  // namespace cordgrasp
