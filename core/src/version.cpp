#include "cordgrasp/core/version.h"

namespace cordgrasp {

const char* version() { return CORDGRASP_VERSION; }

}  // namespace cordgrasp
