#include "cordgrasp/sim/backend_info.h"

#include <LinearMath/btScalar.h>

namespace cordgrasp {

static_assert(sizeof(btScalar) == sizeof(double), "cordgrasp::sim needs bullet-float64");

std::string sim_backend_version() {
  const int v = btGetVersion();
  return "Bullet " + std::to_string(v / 100) + "." + std::to_string(v % 100) +
         (btIsDoublePrecision() ? " (double precision)" : " (single precision)");
}

}  // namespace cordgrasp
