#pragma once
#include <string>

#include "cordgrasp/render/image.h"

namespace cordgrasp {

/// PNG bytes of `image`: 8-bit RGB (alpha dropped) or, with `keep_alpha`, 8-bit RGBA.
/// @throws std::runtime_error when libpng fails or the image is empty.
std::string encode_png(const Image& image, bool keep_alpha = false);

/// Writes `image` as PNG to `path` atomically (temp file + rename), 8-bit RGB or RGBA.
/// @throws InputError naming the path when it cannot be written.
void write_png(const std::string& path, const Image& image, bool keep_alpha = false);

/// Reads any PNG as 8-bit RGBA (grey, palette and 16-bit are converted).
/// @throws InputError naming the path and libpng's message when it cannot be read.
Image read_png(const std::string& path);

}  // namespace cordgrasp
