#pragma once
// parse_name(text, &e): the enumerator of e's type named `text`, through the owning library's
// parse_<enum> (one overload per enum of the parameter structs), so archives and CLI options
// can read any of them by type.
#include <string>

#include "cordgrasp/core/cord_params.h"
#include "cordgrasp/core/grasp_plan.h"
#include "cordgrasp/core/grasp_quality.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/sim/sim_params.h"
#include "cordgrasp/sim/sim_result.h"

namespace cordgrasp {

/// The enumerator named `text` (the enum's own parse_<enum>), by output type.
inline void parse_name(const std::string& text, PlannerKind* e) { *e = parse_planner_kind(text); }
inline void parse_name(const std::string& text, SideCordPolicy* e) {
  *e = parse_side_cord_policy(text);
}
inline void parse_name(const std::string& text, SphereSequence* e) {
  *e = parse_sphere_sequence(text);
}
inline void parse_name(const std::string& text, CordConstruction* e) {
  *e = parse_cord_construction(text);
}
inline void parse_name(const std::string& text, XorBackend* e) { *e = parse_xor_backend(text); }
inline void parse_name(const std::string& text, QualityMode* e) { *e = parse_quality_mode(text); }
inline void parse_name(const std::string& text, LengthUnits* e) { *e = parse_length_units(text); }
inline void parse_name(const std::string& text, ObjectShape* e) { *e = parse_object_shape(text); }
inline void parse_name(const std::string& text, WorldFrame* e) { *e = parse_world_frame(text); }
inline void parse_name(const std::string& text, Protocol* e) { *e = parse_protocol(text); }
inline void parse_name(const std::string& text, Outcome* e) { *e = parse_outcome(text); }

}  // namespace cordgrasp
