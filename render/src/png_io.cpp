#include "cordgrasp/render/png_io.h"

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "cordgrasp/core/atomic_file.h"
#include "cordgrasp/core/error.h"

namespace cordgrasp {

namespace {

void append_bytes(png_structp png, png_bytep data, png_size_t n) {
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), n);
}

void no_flush(png_structp) {}

// libpng reports errors by longjmp: this frame holds no C++ objects with destructors.
// Returns libpng's message on failure, nullptr on success.
const char* encode_rows(const png_bytep* rows, int width, int height, bool keep_alpha,
                        std::string* out) {
  static thread_local char message[256];
  png_structp png = png_create_write_struct(
      PNG_LIBPNG_VER_STRING, message,
      [](png_structp p, png_const_charp msg) {
        std::snprintf(static_cast<char*>(png_get_error_ptr(p)), sizeof message, "%s", msg);
        png_longjmp(p, 1);
      },
      nullptr);
  if (!png) return "cannot create write struct";
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, info ? &info : nullptr);
    return info ? message : "cannot create info struct";
  }
  png_set_write_fn(png, out, append_bytes, no_flush);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8,
               keep_alpha ? PNG_COLOR_TYPE_RGBA : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  // Rendered pictures are mostly flat colour: zlib level 6 without row filters is as small
  // as libpng's adaptive filtering and 2-3 times faster.
  png_set_compression_level(png, 6);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
  png_write_info(png, info);
  if (!keep_alpha) png_set_filler(png, 0, PNG_FILLER_AFTER);  // skip the 4th byte
  png_write_image(png, const_cast<png_bytepp>(rows));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return nullptr;
}

}  // namespace

std::string encode_png(const Image& image, bool keep_alpha) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgba.size() != static_cast<size_t>(image.width) * image.height * 4)
    throw std::runtime_error("encode_png: empty or inconsistent image " +
                             std::to_string(image.width) + "x" + std::to_string(image.height));
  std::vector<png_bytep> rows(image.height);
  for (int y = 0; y < image.height; ++y) rows[y] = const_cast<png_bytep>(image.pixel(0, y));
  std::string bytes;
  bytes.reserve(static_cast<size_t>(image.width) * image.height / 4);
  if (const char* error = encode_rows(rows.data(), image.width, image.height, keep_alpha, &bytes))
    throw std::runtime_error(std::string("encode_png: libpng: ") + error);
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
