#include "cordgrasp/render/backend_info.h"

#include <GL/osmesa.h>
#include <png.h>

namespace cordgrasp {

std::string render_backend_version() {
  return "OSMesa " + std::to_string(OSMESA_MAJOR_VERSION) + "." +
         std::to_string(OSMESA_MINOR_VERSION) + ", libpng " + PNG_LIBPNG_VER_STRING;
}

}  // namespace cordgrasp
