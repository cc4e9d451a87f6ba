#include "cordgrasp/sim/sim_params.h"

#include <stdexcept>

namespace cordgrasp {

const char* to_string(Protocol protocol) {
  switch (protocol) {
    case Protocol::kQuick: return "quick";
    case Protocol::kThorough: return "thorough";
  }
  return "?";
}

Protocol protocol_from_string(const std::string& text) {
  for (Protocol p : {Protocol::kQuick, Protocol::kThorough})
    if (text == to_string(p)) return p;
  throw std::invalid_argument("protocol '" + text + "' is not one of quick, thorough");
}

void apply_protocol(Protocol protocol, SimParams* params) {
  SimParams& p = *params;
  p.protocol = protocol;
  switch (protocol) {
    case Protocol::kQuick:
      p.lift_time_s = 0.5;
      p.lift_hold_s = 0.3;
      p.shake_time_s = 0.5;
      p.rock_frequency_hz = 2.0;  // one period in rock_time_s: tilts both ways
      p.rock_time_s = 0.5;
      p.gravity6_time_s = 0.5;
      p.reach_start_fraction = 0.8;
      p.rest_exit_time_s = 0.1;
      p.exit_on_failure = true;
      return;
    case Protocol::kThorough:
      p.lift_time_s = 1.0;
      p.lift_hold_s = 1.0;
      p.shake_time_s = 1.0;
      p.rock_frequency_hz = 1.0;
      p.rock_time_s = 1.0;
      p.gravity6_time_s = 1.0;
      p.reach_start_fraction = 0.0;
      p.rest_exit_time_s = 0.0;
      p.exit_on_failure = false;
      return;
  }
  throw std::invalid_argument("apply_protocol: unknown protocol");
}

SimParams sim_params_for(Protocol protocol) {
  SimParams params;
  apply_protocol(protocol, &params);
  return params;
}

}  // namespace cordgrasp
