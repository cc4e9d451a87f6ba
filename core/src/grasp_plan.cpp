#include "cordgrasp/core/grasp_plan.h"

#include "cordgrasp/core/enum_names.h"

namespace cordgrasp {
namespace {

constexpr EnumName<PlannerKind> kPlannerNames[] = {{PlannerKind::kCord, "cord"},
                                                   {PlannerKind::kGeneric, "generic"}};

}  // namespace

const char* to_string(PlannerKind planner) { return enum_to_string(planner, kPlannerNames); }

PlannerKind parse_planner_kind(const std::string& text) {
  return parse_enum(text, kPlannerNames, "planner");
}

}  // namespace cordgrasp
