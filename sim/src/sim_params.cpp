#include "cordgrasp/sim/sim_params.h"

#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "cordgrasp/core/enum_names.h"

namespace cordgrasp {
namespace {

constexpr EnumName<ObjectShape> kObjectShapeNames[] = {
    {ObjectShape::kAuto, "auto"},
    {ObjectShape::kConvexHull, "hull"},
    {ObjectShape::kDecomposition, "decomposition"},
    {ObjectShape::kGImpact, "gimpact"}};
constexpr EnumName<Protocol> kProtocolNames[] = {{Protocol::kQuick, "quick"},
                                                 {Protocol::kThorough, "thorough"},
                                                 {Protocol::kStandard, "standard"}};
constexpr EnumName<WorldFrame> kWorldFrameNames[] = {{WorldFrame::kApproachDown, "approach_down"},
                                                     {WorldFrame::kObject, "object"}};

/// Ranges of the SimParams fields (nested ones by their own names) that the simulation needs;
/// every other number must be finite and not negative, but for kMayBeNegative.
struct FieldRange {
  const char* name;
  double lo, hi;
};
constexpr FieldRange kFieldRanges[] = {
    {"time_step_s", 1e-5, 0.02},         {"solver_iterations", 1, 10000},
    {"erp", 0, 1},                       {"friction_erp", 0, 1},
    {"gear_erp", 0, 1},                  {"mu", 0, 10},
    {"cone_edges", 3, 64},               {"soft_finger_radius_m", 0, 0.0499},
    {"contact_stiffness_Npm", 0, 1e9},   {"contact_damping_Nspm", 0, 1e7},
    {"density_kgm3", 1, 1e5},            {"mass_kg", 1e-6, 1e4},
    {"com_offset_x_m", -1, 1},           {"com_offset_y_m", -1, 1},
    {"com_offset_z_m", -1, 1},
    {"concavity", 0, 1},                 {"max_hull_vertices", 4, 100000},
    {"max_input_triangles", -1, 1e7},    {"effort_scale", 1e-3, 100},
    {"squeeze_rad", 0, 3.2},             {"reach_start_fraction", 0, 1},
    {"lift_time_s", 1e-3, 100},          {"lift_hold_s", 0, 100},
    {"shake_time_s", 1e-3, 100},         {"rock_time_s", 1e-3, 100},
    {"shake_frequency_hz", 1e-3, 100},   {"rock_frequency_hz", 1e-3, 100},
    {"gravity6_time_s", 1e-3, 100},      {"settle_time_s", 0, 100},
    {"squeeze_max_time_s", 0, 100},      {"rest_exit_time_s", 0, 100},
    {"trace_interval_s", 0, 10},         {"armature_kgm2", 0, 1e3},
};
constexpr const char* kMayBeNegative[] = {"connect_distance"};

/// Archive of check_sim_params: visits every field, nested structs by their own fields.
class RangeCheck {
 public:
  template <typename T>
  void Visit(const NameValuePair<T>& nvp) {
    check(nvp.name, *nvp.value);
  }

 private:
  template <typename T>
  void check(const char* name, const T& value) {
    if constexpr (std::is_same_v<T, bool> || std::is_enum_v<T> ||
                  std::is_same_v<T, std::string>) {
      return;
    } else if constexpr (std::is_arithmetic_v<T>) {
      check_number(name, static_cast<double>(value));
    } else if constexpr (std::is_same_v<T, std::optional<double>>) {
      if (value) check_number(name, *value);
    } else {
      T copy = value;  // Serialize takes field addresses
      copy.Serialize(this);
    }
  }
  static void check_number(const char* name, double value) {
    const std::string field(name);
    std::ostringstream why;
    for (const FieldRange& r : kFieldRanges)
      if (field == r.name) {
        if (std::isfinite(value) && value >= r.lo && value <= r.hi) return;
        why << field << ": " << value << " is not in [" << r.lo << ", " << r.hi << "]";
        throw std::invalid_argument(why.str());
      }
    if (!std::isfinite(value)) throw std::invalid_argument(field + ": not a finite number");
    for (const char* n : kMayBeNegative)
      if (field == n) return;
    if (value < 0.0) {
      why << field << ": " << value << " is negative";
      throw std::invalid_argument(why.str());
    }
  }
};

/// The "(preset)" fields of SimParams, one row per protocol (docs/physics.md §3, §6).
struct ProtocolPreset {
  Protocol protocol;
  double time_step_s;
  int solver_iterations;
  double settle_time_s, lift_height_m, lift_time_s, lift_hold_s;
  double shake_amplitude_m, shake_frequency_hz, shake_time_s;
  double rock_angle_deg, rock_frequency_hz;  ///< one period in rock_time_s: tilts both ways
  double rock_time_s;
  bool shake_all_axes_at_once;
  double gravity6_time_s, reach_start_fraction, reach_start_gap_m, squeeze_travel_m;
  double squeeze_max_time_s, rest_exit_time_s;
  bool exit_on_failure;
};
// clang-format off
constexpr ProtocolPreset kPresets[] = {
    // protocol           step        iter settle lift m, s  hold shake m, Hz, s   rock °, Hz, s   all axes g6  reach gap  travel squeeze rest exit
    {Protocol::kQuick,    1.0 / 960.0, 50, 0.05, 0.10, 0.5,  0.3, 0.02,  2.0, 0.5,  15.0, 2.0, 0.5,  false, 0.5, 0.8, 0.0,  0.0,  0.5, 0.1, true},
    {Protocol::kStandard, 1.0 / 960.0, 30, 0.01, 0.03, 0.27, 0.3, 0.005, 4.0, 0.25, 15.0, 2.0, 0.5,  true,  0.5, 0.0, 3e-3, 1e-3, 0.3, 0.1, true},
    {Protocol::kThorough, 1.0 / 960.0, 50, 0.05, 0.10, 1.0,  1.0, 0.02,  2.0, 1.0,  15.0, 1.0, 1.0,  false, 1.0, 0.0, 0.0,  0.0,  0.5, 0.0, false},
};
// clang-format on

}  // namespace

void check_sim_params(const SimParams& params) {
  RangeCheck check;
  SimParams copy = params;
  copy.Serialize(&check);
}

const char* to_string(ObjectShape shape) { return enum_to_string(shape, kObjectShapeNames); }
ObjectShape parse_object_shape(const std::string& text) {
  return parse_enum(text, kObjectShapeNames, "object shape");
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
  for (const ProtocolPreset& preset : kPresets) {
    if (preset.protocol != protocol) continue;
    SimParams& p = *params;
    p.protocol = protocol;
    p.time_step_s = preset.time_step_s;
    p.solver_iterations = preset.solver_iterations;
    p.settle_time_s = preset.settle_time_s;
    p.lift_height_m = preset.lift_height_m;
    p.lift_time_s = preset.lift_time_s;
    p.lift_hold_s = preset.lift_hold_s;
    p.shake_amplitude_m = preset.shake_amplitude_m;
    p.shake_frequency_hz = preset.shake_frequency_hz;
    p.shake_time_s = preset.shake_time_s;
    p.rock_angle_rad = preset.rock_angle_deg * M_PI / 180.0;
    p.rock_frequency_hz = preset.rock_frequency_hz;
    p.rock_time_s = preset.rock_time_s;
    p.shake_all_axes_at_once = preset.shake_all_axes_at_once;
    p.gravity6_time_s = preset.gravity6_time_s;
    p.reach_start_fraction = preset.reach_start_fraction;
    p.reach_start_gap_m = preset.reach_start_gap_m;
    p.squeeze_travel_m = preset.squeeze_travel_m;
    p.squeeze_max_time_s = preset.squeeze_max_time_s;
    p.rest_exit_time_s = preset.rest_exit_time_s;
    p.exit_on_failure = preset.exit_on_failure;
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
