#include "cordgrasp/render/png_io.h"

#include <png.h>

#include <cstring>
#include <stdexcept>

#include "cordgrasp/core/atomic_file.h"
#include "cordgrasp/core/error.h"

namespace cordgrasp {

std::string encode_png(const Image& image, bool keep_alpha) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgba.size() != static_cast<size_t>(image.width) * image.height * 4)
    throw std::runtime_error("encode_png: empty or inconsistent image " +
                             std::to_string(image.width) + "x" + std::to_string(image.height));
  // libpng's simplified API drops alpha itself when asked for RGB from an RGBA buffer only
  // by compositing on a background; drop it explicitly instead so colours stay exact.
  std::vector<std::uint8_t> rgb;
  const void* buffer = image.rgba.data();
  png_image png;
  std::memset(&png, 0, sizeof(png));
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width);
  png.height = static_cast<png_uint_32>(image.height);
  png.format = keep_alpha ? PNG_FORMAT_RGBA : PNG_FORMAT_RGB;
  if (!keep_alpha) {
    rgb.resize(static_cast<size_t>(image.width) * image.height * 3);
    for (size_t i = 0, n = rgb.size() / 3; i < n; ++i)
      std::memcpy(&rgb[3 * i], &image.rgba[4 * i], 3);
    buffer = rgb.data();
  }
  png_alloc_size_t size = 0;
  if (!png_image_write_to_memory(&png, nullptr, &size, 0, buffer, 0, nullptr))
    throw std::runtime_error(std::string("encode_png: libpng: ") + png.message);
  std::string bytes(size, '\0');
  if (!png_image_write_to_memory(&png, bytes.data(), &size, 0, buffer, 0, nullptr))
    throw std::runtime_error(std::string("encode_png: libpng: ") + png.message);
  bytes.resize(size);
  return bytes;
}

void write_png(const std::string& path, const Image& image, bool keep_alpha) {
  write_file_atomically(path, encode_png(image, keep_alpha));
}

Image read_png(const std::string& path) {
  png_image png;
  std::memset(&png, 0, sizeof(png));
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, path.c_str()))
    throw InputError("read_png: '" + path + "': " + png.message);
  png.format = PNG_FORMAT_RGBA;
  Image image;
  image.width = static_cast<int>(png.width);
  image.height = static_cast<int>(png.height);
  image.rgba.resize(PNG_IMAGE_SIZE(png));
  if (!png_image_finish_read(&png, nullptr, image.rgba.data(), 0, nullptr)) {
    const std::string message = png.message;
    png_image_free(&png);
    throw InputError("read_png: '" + path + "': " + message);
  }
  return image;
}

}  // namespace cordgrasp
