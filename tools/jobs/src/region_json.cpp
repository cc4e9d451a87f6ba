#include "cordgrasp/jobs/region_json.h"

#include "cordgrasp/core/error.h"
#include "json_util.h"

namespace cordgrasp {

nlohmann::json region_to_json(const GraspRegion& r) {
  nlohmann::json cords = nlohmann::json::array();
  for (const Polyline3& cord : r.front_cords) {
    nlohmann::json points = nlohmann::json::array();
    for (const auto& p : cord) points.push_back(to_json(p));
    cords.push_back(std::move(points));
  }
  return {{"p1", to_json(r.p1)},
          {"p2", to_json(r.p2)},
          {"p3", to_json(r.p3)},
          {"normal", to_json(r.normal)},
          {"p_l", to_json(r.p_l)},
          {"p_r", to_json(r.p_r)},
          {"p_m", to_json(r.p_m)},
          {"case", r.cord_case == CordCase::kI ? "I" : "II"},
          {"n", r.n},
          {"front_cords", std::move(cords)},
          {"xi_m", r.xi_m},
          {"chi_m2", r.chi_m2},
          {"from_local_improvement", r.from_local_improvement}};
}

GraspRegion region_from_json(const nlohmann::json& j) {
  const auto field = [&j](const char* name) -> const nlohmann::json& {
    if (!j.is_object() || !j.contains(name))
      throw InputError(std::string("region: missing field '") + name + "'");
    return j.at(name);
  };
  const auto vec = [&field](const char* name) {
    try {
      return vec3_from_json(field(name));
    } catch (const nlohmann::json::exception&) {
      throw InputError(std::string("region: field '") + name + "' is not [x, y, z]");
    }
  };
  GraspRegion r;
  r.p1 = vec("p1");
  r.p2 = vec("p2");
  r.p3 = vec("p3");
  r.normal = vec("normal");
  r.p_l = vec("p_l");
  r.p_r = vec("p_r");
  r.p_m = vec("p_m");
  try {
    const nlohmann::json& c = field("case");  // "I" / "II" (also 1 / 2)
    if (c == "I" || c == 1)
      r.cord_case = CordCase::kI;
    else if (c == "II" || c == 2)
      r.cord_case = CordCase::kII;
    else
      throw InputError("region: field 'case' must be \"I\" or \"II\"");
    r.n = field("n").get<int>();
    for (const auto& cord : field("front_cords")) {
      Polyline3 line;
      for (const auto& p : cord) line.push_back(vec3_from_json(p));
      r.front_cords.push_back(std::move(line));
    }
    r.xi_m = field("xi_m").get<double>();
    r.chi_m2 = field("chi_m2").get<double>();
    r.from_local_improvement = j.value("from_local_improvement", false);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(std::string("region: malformed field: ") + e.what());
  }
  if (r.n < 0 || r.front_cords.size() != static_cast<size_t>(2 * r.n + 1))
    throw InputError("region: front_cords holds " + std::to_string(r.front_cords.size()) +
                     " polylines, expected 2n + 1 = " + std::to_string(2 * r.n + 1));
  return r;
}

}  // namespace cordgrasp
