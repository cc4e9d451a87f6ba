#pragma once
// Pixel statistics shared by the render tests.
#include <Eigen/Core>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <string>

#include "cordgrasp/render/image.h"
#include "cordgrasp/render/png_io.h"

namespace cordgrasp::test {

/// Pixels selected by a predicate on (r, g, b): count and centroid of their centres [px].
struct PixelSet {
  int count = 0;
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  int x_min = 1 << 30, x_max = -1, y_min = 1 << 30, y_max = -1;
};

inline PixelSet select_pixels(const Image& image, const std::function<bool(int, int, int)>& pred) {
  PixelSet s;
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      if (!pred(p[0], p[1], p[2])) continue;
      ++s.count;
      sum += Eigen::Vector2d(x + 0.5, y + 0.5);
      s.x_min = std::min(s.x_min, x);
      s.x_max = std::max(s.x_max, x);
      s.y_min = std::min(s.y_min, y);
      s.y_max = std::max(s.y_max, y);
    }
  if (s.count > 0) s.centroid = sum / s.count;
  return s;
}

/// Pixels that are not the white background.
inline PixelSet non_white(const Image& image, int below = 250) {
  return select_pixels(
      image, [below](int r, int g, int b) { return r < below || g < below || b < below; });
}

/// Pixels of the same hue as `rgba` at any brightness (shading), not near-white.
inline int pixels_of_hue(const Image& image, const Eigen::Vector4d& rgba) {
  const Eigen::Vector3d ref = rgba.head<3>().normalized();
  return select_pixels(image,
                       [&](int r, int g, int b) {
                         const Eigen::Vector3d c(r, g, b);
                         return c.norm() > 30 && c.normalized().dot(ref) > 0.995 &&
                                c.minCoeff() < 235;
                       })
      .count;
}

/// Colour of pixel (x, y) as doubles in [0, 255].
inline Eigen::Vector3d rgb_at(const Image& image, int x, int y) {
  const std::uint8_t* p = image.pixel(x, y);
  return Eigen::Vector3d(p[0], p[1], p[2]);
}

/// Writes `image` as <name>.png into $CORDGRASP_TEST_IMAGE_DIR when that is set, to look at.
inline void save_for_inspection(const Image& image, const std::string& name) {
  const char* dir = std::getenv("CORDGRASP_TEST_IMAGE_DIR");
  if (dir && *dir) write_png(std::string(dir) + "/" + name + ".png", image);
}

}  // namespace cordgrasp::test
