#pragma once
#include <string>

namespace cordgrasp {

/// "OSMesa <major>.<minor>, libpng <version>, FreeType <version>": what render was built with.
std::string render_backend_version();

/// "OpenGL 4.5 (Core Profile) Mesa 22.3.6, llvmpipe (...)": what an OSMesa context created now
/// provides (takes a few ms), or "OpenGL unavailable: <reason>".
std::string render_gl_info();

}  // namespace cordgrasp
