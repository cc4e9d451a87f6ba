#pragma once
#include <string>

namespace cordgrasp {

/// "Bullet <version> (double precision)": the physics/collision backend sim was built with.
std::string sim_backend_version();

}  // namespace cordgrasp
