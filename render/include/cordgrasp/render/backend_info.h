#pragma once
#include <string>

namespace cordgrasp {

/// "OSMesa <major>.<minor>, libpng <version>": the offscreen renderer render was built with.
std::string render_backend_version();

}  // namespace cordgrasp
