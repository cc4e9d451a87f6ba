#include "cordgrasp/render/image.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cordgrasp {

std::uint8_t to_byte(double component) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(component, 0.0, 1.0) * 255.0));
}

Image make_image(int width_px, int height_px, const Eigen::Vector4d& rgba) {
  if (width_px < 0 || height_px < 0)
    throw std::invalid_argument("make_image: negative size " + std::to_string(width_px) + "x" +
                                std::to_string(height_px));
  Image image;
  image.width = width_px;
  image.height = height_px;
  image.rgba.resize(static_cast<size_t>(width_px) * height_px * 4);
  const std::uint8_t c[4] = {to_byte(rgba[0]), to_byte(rgba[1]), to_byte(rgba[2]),
                             to_byte(rgba[3])};
  for (size_t i = 0; i < image.rgba.size(); i += 4) std::copy(c, c + 4, image.rgba.begin() + i);
  return image;
}

void blit_image(Image& dst, const Image& src, int x, int y) {
  const int x0 = std::max(0, x), x1 = std::min(dst.width, x + src.width);
  if (x1 <= x0) return;
  for (int row = std::max(0, y); row < std::min(dst.height, y + src.height); ++row)
    std::copy(src.pixel(x0 - x, row - y), src.pixel(x0 - x, row - y) + 4 * (x1 - x0),
              dst.pixel(x0, row));
}

void fill_rect(Image& image, int x, int y, int w, int h, const Eigen::Vector4d& rgba) {
  const std::uint8_t c[4] = {to_byte(rgba[0]), to_byte(rgba[1]), to_byte(rgba[2]),
                             to_byte(rgba[3])};
  for (int row = std::max(0, y); row < std::min(image.height, y + h); ++row)
    for (int col = std::max(0, x); col < std::min(image.width, x + w); ++col)
      std::copy(c, c + 4, image.pixel(col, row));
}

}  // namespace cordgrasp
