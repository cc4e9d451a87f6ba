#include "cordgrasp/render/backend_info.h"

#include <GL/osmesa.h>
#include <ft2build.h>
#include FT_FREETYPE_H
#include <png.h>

#include <exception>

#include "osmesa_context.h"

namespace cordgrasp {

std::string render_backend_version() {
  return "OSMesa " + std::to_string(OSMESA_MAJOR_VERSION) + "." +
         std::to_string(OSMESA_MINOR_VERSION) + ", libpng " + PNG_LIBPNG_VER_STRING +
         ", FreeType " + std::to_string(FREETYPE_MAJOR) + "." + std::to_string(FREETYPE_MINOR) +
         "." + std::to_string(FREETYPE_PATCH);
}

std::string render_gl_info() {
  try {
    return render_detail::OsMesaContext().description();
  } catch (const std::exception& e) {
    return std::string("OpenGL unavailable: ") + e.what();
  }
}

}  // namespace cordgrasp
