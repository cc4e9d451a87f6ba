#include "cordgrasp/sim/sim_params.h"

#include <stdexcept>

#include "cordgrasp/core/enum_names.h"

namespace cordgrasp {
namespace {

constexpr EnumName<ObjectShape> kObjectShapeNames[] = {
    {ObjectShape::kAuto, "auto"},
    {ObjectShape::kConvexHull, "hull"},
    {ObjectShape::kDecomposition, "decomposition"},
    {ObjectShape::kGImpact, "gimpact"}};
constexpr EnumName<SqueezeDirection> kSqueezeDirectionNames[] = {
    {SqueezeDirection::kActor, "actor"}, {SqueezeDirection::kContactNormals, "contacts"},
    {SqueezeDirection::kBalanced, "balanced"}};
constexpr EnumName<ObjectFixed> kObjectFixedNames[] = {{ObjectFixed::kNever, "never"},
                                                       {ObjectFixed::kReach, "reach"},
                                                       {ObjectFixed::kClose, "close"}};
constexpr EnumName<Protocol> kProtocolNames[] = {{Protocol::kQuick, "quick"},
                                                 {Protocol::kThorough, "thorough"},
                                                 {Protocol::kFast, "fast"},
                                                 {Protocol::kStandard, "standard"}};
constexpr EnumName<WorldFrame> kWorldFrameNames[] = {{WorldFrame::kApproachDown, "approach_down"},
                                                     {WorldFrame::kObject, "object"}};

}  // namespace

const char* to_string(ObjectShape shape) { return enum_to_string(shape, kObjectShapeNames); }
ObjectShape parse_object_shape(const std::string& text) {
  return parse_enum(text, kObjectShapeNames, "object shape");
}

const char* to_string(SqueezeDirection direction) {
  return enum_to_string(direction, kSqueezeDirectionNames);
}
SqueezeDirection parse_squeeze_direction(const std::string& text) {
  return parse_enum(text, kSqueezeDirectionNames, "squeeze direction");
}

const char* to_string(ObjectFixed fixed) { return enum_to_string(fixed, kObjectFixedNames); }
ObjectFixed parse_object_fixed(const std::string& text) {
  return parse_enum(text, kObjectFixedNames, "object fixed");
}

const char* to_string(WorldFrame frame) { return enum_to_string(frame, kWorldFrameNames); }
WorldFrame parse_world_frame(const std::string& text) {
  return parse_enum(text, kWorldFrameNames, "world frame");
}

const char* to_string(Protocol protocol) { return enum_to_string(protocol, kProtocolNames); }
Protocol parse_protocol(const std::string& text) {
  return parse_enum(text, kProtocolNames, "protocol");
}

void apply_protocol(Protocol protocol, SimParams* params) {
  SimParams& p = *params;
  p.protocol = protocol;
  switch (protocol) {
    case Protocol::kQuick:
    case Protocol::kFast:
      p.time_step_s = protocol == Protocol::kFast ? 1.0 / 480.0 : 1.0 / 960.0;
      p.lift_time_s = 0.5;
      p.lift_hold_s = 0.3;
      p.shake_time_s = 0.5;
      p.rock_frequency_hz = 2.0;  // one period in rock_time_s: tilts both ways
      p.rock_time_s = 0.5;
      p.shake_all_axes_at_once = protocol == Protocol::kFast;  // one shake, one rock segment
      p.gravity6_time_s = 0.5;
      p.reach_start_fraction = 0.8;
      p.reach_start_gap_m = 0.0;
      p.squeeze_travel_m = 0.0;
      p.squeeze_max_time_s = 0.5;
      p.rest_exit_time_s = 0.1;
      p.exit_on_failure = true;
      return;
    case Protocol::kStandard:
      p.time_step_s = 1.0 / 960.0;
      p.lift_time_s = 0.5;
      p.lift_hold_s = 0.3;
      p.shake_time_s = 0.5;
      p.rock_frequency_hz = 2.0;
      p.rock_time_s = 0.5;
      p.shake_all_axes_at_once = true;
      p.gravity6_time_s = 0.5;
      p.reach_start_fraction = 0.0;
      p.reach_start_gap_m = 3e-3;
      p.squeeze_travel_m = 1e-3;
      p.squeeze_max_time_s = 0.3;
      p.rest_exit_time_s = 0.1;
      p.exit_on_failure = true;
      return;
    case Protocol::kThorough:
      p.time_step_s = 1.0 / 960.0;
      p.lift_time_s = 1.0;
      p.lift_hold_s = 1.0;
      p.shake_time_s = 1.0;
      p.rock_frequency_hz = 1.0;
      p.rock_time_s = 1.0;
      p.shake_all_axes_at_once = false;
      p.gravity6_time_s = 1.0;
      p.reach_start_fraction = 0.0;
      p.reach_start_gap_m = 0.0;
      p.squeeze_travel_m = 0.0;
      p.squeeze_max_time_s = 0.5;
      p.rest_exit_time_s = 0.0;
      p.exit_on_failure = false;
      return;
  }
  throw std::invalid_argument("apply_protocol: unknown protocol");
}

void apply_sim_overrides(const SimOverrides& overrides, SimParams* params) {
  if (overrides.mass_kg) params->mass_kg = overrides.mass_kg;
  if (overrides.density_kgm3) params->density_kgm3 = *overrides.density_kgm3;
  if (overrides.squeeze_weight_factor)
    params->squeeze_weight_factor = *overrides.squeeze_weight_factor;
}

SimOverrides sim_overrides_or(const SimOverrides& given, const SimOverrides& recorded) {
  SimOverrides out = given;
  if (!given.mass_kg && !given.density_kgm3) {
    out.mass_kg = recorded.mass_kg;
    out.density_kgm3 = recorded.density_kgm3;
  }
  if (!given.squeeze_weight_factor) out.squeeze_weight_factor = recorded.squeeze_weight_factor;
  return out;
}

SimParams sim_params_for(Protocol protocol) {
  SimParams params;
  apply_protocol(protocol, &params);
  return params;
}

}  // namespace cordgrasp
