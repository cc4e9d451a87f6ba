#include "cordgrasp/sim/sim_params.h"

#include "cordgrasp/core/enum_names.h"

namespace cordgrasp {
namespace {

constexpr EnumName<ObjectShape> kObjectShapeNames[] = {
    {ObjectShape::kAuto, "auto"},
    {ObjectShape::kConvexHull, "hull"},
    {ObjectShape::kDecomposition, "decomposition"},
    {ObjectShape::kGImpact, "gimpact"}};
constexpr EnumName<SqueezeDirection> kSqueezeDirectionNames[] = {
    {SqueezeDirection::kActor, "actor"}, {SqueezeDirection::kContactNormals, "contacts"}};
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

const char* to_string(WorldFrame frame) { return enum_to_string(frame, kWorldFrameNames); }
WorldFrame parse_world_frame(const std::string& text) {
  return parse_enum(text, kWorldFrameNames, "world frame");
}

}  // namespace cordgrasp
