#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace cordgrasp {

/// An 8-bit RGBA raster, rows top to bottom, 4 bytes per pixel (R, G, B, A).
struct Image {
  int width = 0;                   ///< [px]
  int height = 0;                  ///< [px]
  std::vector<std::uint8_t> rgba;  ///< width · height · 4 bytes

  /// First byte of pixel (x, y), y counted from the top. No bounds check.
  std::uint8_t* pixel(int x, int y) {
    return rgba.data() + 4 * (static_cast<size_t>(y) * width + x);
  }
  const std::uint8_t* pixel(int x, int y) const {
    return rgba.data() + 4 * (static_cast<size_t>(y) * width + x);
  }
};

/// Image of `width_px` × `height_px` filled with colour `rgba` (components in [0, 1]).
/// @throws std::invalid_argument for negative sizes.
Image make_image(int width_px, int height_px,
                 const Eigen::Vector4d& rgba = Eigen::Vector4d(1.0, 1.0, 1.0, 1.0));

/// Copies `src` into `dst` with its top-left corner at (x, y) px, clipped to `dst`.
void blit_image(Image& dst, const Image& src, int x, int y);

/// Fills the rectangle [x, x + w) × [y, y + h) px of `image` (clipped) with `rgba` in [0, 1].
void fill_rect(Image& image, int x, int y, int w, int h, const Eigen::Vector4d& rgba);

/// 8-bit colour of a [0, 1] component (clamped, rounded).
std::uint8_t to_byte(double component);

}  // namespace cordgrasp
