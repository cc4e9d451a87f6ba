#include "cordgrasp/jobs/plan_json.h"

#include <cmath>

#include "cordgrasp/jobs/region_json.h"
#include "cordgrasp/jobs/text_format.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "cordgrasp/core/atomic_file.h"
#include "cordgrasp/core/error.h"
#include "cordgrasp/jobs/json_completeness.h"
#include "json_util.h"
#include "params_json.h"

namespace cordgrasp {

namespace {

constexpr const char* kFormat = "cordgrasp-plan";
constexpr int kFormatVersion = 3;

/// Largest |coordinate| of a position in a plan [m]: anything farther is not a grasp.
constexpr double kMaxPlanCoordinate_m = 1e3;
/// How far a stored quaternion's norm may be from 1 before the plan is refused.
constexpr double kUnitQuaternionTol = 1e-6;
/// How far a joint value may lie outside its limits (rounding of the writer) [rad or m].
constexpr double kJointLimitTol = 1e-9;

// The rotation is stored twice: as a quaternion for people and other tools, and as its nine
// matrix entries (row-major), which restore the pose bit for bit, so that a plan re-read from
// plan.json simulates exactly as the one in memory.
nlohmann::json pose_json(const Eigen::Isometry3d& X) {
  const Eigen::Quaterniond q(X.linear());
  nlohmann::json rows = nlohmann::json::array();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) rows.push_back(X.linear()(r, c));
  return {{"position_m", to_json(Eigen::Vector3d(X.translation()))},
          {"quaternion_wxyz", {q.w(), q.x(), q.y(), q.z()}},
          {"rotation_rowmajor", rows}};
}

double finite_number(const nlohmann::json& j, const std::string& where) {
  if (!j.is_number()) throw InputError(where + ": not a number");
  const double v = j.get<double>();
  if (!std::isfinite(v)) throw InputError(where + ": not finite");
  return v;
}

/// j[key], which must be present, or InputError naming where.key.
const nlohmann::json& member(const nlohmann::json& j, const char* key, const std::string& where) {
  if (!j.is_object()) throw InputError(where + ": expected a JSON object");
  if (!j.contains(key)) throw InputError(where + "." + key + ": missing");
  return j.at(key);
}

/// j[key] as a finite number, `fallback` when absent (null is not absent: NaN is written so).
double optional_number(const nlohmann::json& j, const char* key, double fallback,
                       const std::string& where) {
  return j.contains(key) ? finite_number(j.at(key), where + "." + key) : fallback;
}

/// j[key] as true/false, `fallback` when absent.
bool optional_bool(const nlohmann::json& j, const char* key, bool fallback,
                   const std::string& where) {
  if (!j.contains(key)) return fallback;
  if (!j.at(key).is_boolean()) throw InputError(where + "." + key + ": not true or false");
  return j.at(key).get<bool>();
}

/// j[key] as a string, which must be present.
std::string string_member(const nlohmann::json& j, const char* key, const std::string& where) {
  const nlohmann::json& v = member(j, key, where);
  if (!v.is_string()) throw InputError(where + "." + key + ": not a string");
  return v.get<std::string>();
}

/// j[key], which must be a JSON array.
const nlohmann::json& array_member(const nlohmann::json& j, const char* key,
                                   const std::string& where) {
  const nlohmann::json& v = member(j, key, where);
  if (!v.is_array()) throw InputError(where + "." + key + ": expected a JSON array");
  return v;
}

Eigen::Vector3d point_from_json(const nlohmann::json& j, const std::string& where) {
  if (!j.is_array() || j.size() != 3) throw InputError(where + ": expected [x, y, z]");
  Eigen::Vector3d p;
  for (int i = 0; i < 3; ++i) {
    p[i] = finite_number(j[static_cast<size_t>(i)], where + "[" + std::to_string(i) + "]");
    if (std::abs(p[i]) > kMaxPlanCoordinate_m)
      throw InputError(where + ": " + format_number(p[i]) + " m is farther than " +
                       format_number(kMaxPlanCoordinate_m) + " m");
  }
  return p;
}

Eigen::Isometry3d pose_from_json(const nlohmann::json& j, const std::string& where) {
  if (!j.is_object()) throw InputError(where + ": expected {position_m, quaternion_wxyz}");
  if (!j.contains("quaternion_wxyz")) throw InputError(where + ".quaternion_wxyz: missing");
  if (!j.contains("position_m")) throw InputError(where + ".position_m: missing");
  const auto& q = j.at("quaternion_wxyz");
  const std::string qw = where + ".quaternion_wxyz";
  if (!q.is_array() || q.size() != 4) throw InputError(qw + ": expected [w, x, y, z]");
  Eigen::Vector4d wxyz;
  for (int i = 0; i < 4; ++i)
    wxyz[i] = finite_number(q[static_cast<size_t>(i)], qw + "[" + std::to_string(i) + "]");
  if (std::abs(wxyz.norm() - 1.0) > kUnitQuaternionTol)
    throw InputError(qw + ": not a unit quaternion (norm " + format_number(wxyz.norm()) + ")");
  const Eigen::Quaterniond quat(wxyz[0], wxyz[1], wxyz[2], wxyz[3]);
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = quat.normalized().toRotationMatrix();
  if (j.contains("rotation_rowmajor")) {
    const auto& m = j.at("rotation_rowmajor");
    const std::string mw = where + ".rotation_rowmajor";
    if (!m.is_array() || m.size() != 9) throw InputError(mw + ": expected 9 numbers");
    Eigen::Matrix3d R;
    for (int k = 0; k < 9; ++k)
      R(k / 3, k % 3) = finite_number(m[static_cast<size_t>(k)], mw);
    if ((R - X.linear()).cwiseAbs().maxCoeff() > 1e-6)
      throw InputError(mw + ": does not match quaternion_wxyz");
    X.linear() = R;  // exact: the matrix the planner had
  }
  X.translation() = point_from_json(j.at("position_m"), where + ".position_m");
  return X;
}

nlohmann::json joints_json(const HandModel& hand, const Eigen::VectorXd& q) {
  nlohmann::json out = nlohmann::json::object();
  for (size_t j = 0; j < hand.joints.size(); ++j)
    if (hand.joints[j].is_moving() && static_cast<Eigen::Index>(j) < q.size())
      out[hand.joints[j].name] = q[static_cast<Eigen::Index>(j)];
  return out;
}

/// Joint values by name; `where` is the JSON path with the file, e.g. "p.json: grasps[0].joints".
Eigen::VectorXd joints_from_json(const HandModel& hand, const nlohmann::json& j,
                                 const std::string& where) {
  Eigen::VectorXd q = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(hand.joints.size()));
  if (!j.is_object()) throw InputError(where + ": expected {joint name: value}");
  for (const auto& [name, value] : j.items()) {
    const int index = find_joint(hand, name);
    if (index < 0)
      throw InputError(where + ": names joint '" + name + "' that hand '" + hand.name +
                       "' does not have");
    const double v = finite_number(value, where + "." + name);
    const Joint& joint = hand.joints[static_cast<size_t>(index)];
    if (v < joint.lower - kJointLimitTol || v > joint.upper + kJointLimitTol)
      throw InputError(where + "." + name + ": " + format_number(v) +
                       " is outside the joint's limits [" + format_number(joint.lower) + ", " +
                       format_number(joint.upper) + "]");
    q[index] = v;
  }
  return q;
}

nlohmann::json optional_json(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

nlohmann::json stats_json(const PlanStats& s) {
  nlohmann::json j = params_to_json(s);
  j["machine_dependent"] = s.timed_out;  // for readers: another machine may plan otherwise
  return j;
}

/// Plan files from before a count was added lack its key: it reads as 0.
PlanStats stats_from_json(const nlohmann::json& j, const std::string& source) {
  PlanStats s;
  JsonReadArchive archive(j, source, "stats", MissingKey::kKeepDefault);
  s.Serialize(&archive);
  return s;
}

// The layout of plan.json "parameters": the planner, PlanParams' fields at the top level (the
// keys of format_version 1 plans: grasps, time_limit_s, seed, finger, ...), the palm width and
// the cord planner's CordParams (null for the generic planner).
struct PlanParameters {
  PlanDocument* doc;

  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit(make_nvp("planner", &doc->planner));
    doc->params.Serialize(a);
    a->Visit(make_nvp("palm_width_m", &doc->palm_width_m));
    a->Visit(make_nvp("cord", &doc->cord));
  }
};

}  // namespace

nlohmann::json plan_to_json(const PlanDocument& plan, const HandModel& hand) {
  nlohmann::json grasps = nlohmann::json::array();
  if (plan.validation && plan.validation->grasps.size() != plan.grasps.size())
    throw std::invalid_argument("plan_to_json: " + std::to_string(plan.grasps.size()) +
                                " grasps but " +
                                std::to_string(plan.validation->grasps.size()) + " verdicts");
  for (const Grasp& g : plan.grasps) {
    nlohmann::json contacts = nlohmann::json::array();
    for (const Contact& c : g.contacts) {
      const std::string link = c.link >= 0 && c.link < static_cast<int>(hand.links.size())
                                   ? hand.links[static_cast<size_t>(c.link)].name
                                   : std::string();
      contacts.push_back({{"link", link}, {"point_m", to_json(c.p_O)}, {"normal", to_json(c.n_O)}});
    }
    grasps.push_back(
        {{"hand_pose", pose_json(g.X_OB)},
         {"gcp_pose", pose_json(g.X_OG)},
         {"joints", joints_json(hand, g.q)},
         {"preshape_joints", joints_json(hand, g.q_preshape)},
         {"contacts", contacts},
         {"force_closure", g.force_closure},
         {"epsilon", g.epsilon},
         {"alpha_rad", g.alpha_rad},
         {"alpha_approach_rad", g.alpha_approach_rad},
         {"measures", params_to_json(g.measures)},
         {"chi_m2", optional_json(g.chi_m2)},
         {"region_rank", g.region_rank ? nlohmann::json(*g.region_rank) : nlohmann::json(nullptr)},
         {"region", g.region ? region_to_json(*g.region) : nlohmann::json(nullptr)},
         {"timings_s",
          {{"exploration", g.times.exploration_s},
           {"finger", g.times.finger_s},
           {"quality", g.times.quality_s}}}});
    if (plan.validation)
      grasps.back()["validation"] = params_to_json(plan.validation->grasps[grasps.size() - 1]);
  }
  nlohmann::json out = {{"format", kFormat},
          {"format_version", kFormatVersion},
          {"cordgrasp_version", plan.cordgrasp_version},
          {"inputs",
           {{"hand",
             {{"name", plan.hand_name}, {"path", plan.hand_path}, {"urdf_path", plan.urdf_path}}},
            {"object",
             {{"path", plan.object_path},
              {"name", plan.object_name},
              {"units", plan.object_units},
              {"scale", plan.object_scale},
              {"triangles", plan.object_triangles}}}}},
          {"parameters", [&plan] {
             PlanDocument copy = plan;  // the visitor takes field addresses
             JsonWriteArchive archive;
             PlanParameters{&copy}.Serialize(&archive);
             return archive.json();
           }()},
          {"stats", stats_json(plan.stats)},
          {"grasps", grasps}};
  if (plan.validation)
    out["validation"] = {{"parameters", params_to_json(plan.validation->params)},
                         {"stats", params_to_json(plan.validation->stats)}};
  mark_completeness(&out, plan.interrupted);
  return out;
}

void write_plan_file(const std::string& path, const PlanDocument& plan, const HandModel& hand) {
  write_file_atomically(path, plan_to_json(plan, hand).dump(2) + "\n");
}

void upgrade_plan_from_version_2(nlohmann::json* plan) {
  nlohmann::json& j = *plan;
  // Dropped in 3: the candidate filters (they only chose which grasps were planned).
  if (j.contains("parameters") && j["parameters"].is_object()) j["parameters"].erase("candidate");
  if (j.contains("stats") && j["stats"].is_object()) j["stats"].erase("filtered");
  // Keys that version 2 plans written before them lack, as version 2 read them.
  if (j.contains("inputs") && j["inputs"].is_object() && j["inputs"].contains("object") &&
      j["inputs"]["object"].is_object() && !j["inputs"]["object"].contains("scale"))
    j["inputs"]["object"]["scale"] = 1.0;
  // New in 3: the diversity rule belongs to the planner (parameters.diversity); version 2
  // had it in validated planning only, so plain version-2 plans record none.
  nlohmann::json diversity = params_to_json(DiversityParams{0.0, 0.0, 0.0});
  if (j.contains("validation") && j["validation"].is_object() &&
      j["validation"].contains("parameters") && j["validation"]["parameters"].is_object()) {
    nlohmann::json& v = j["validation"]["parameters"];
    for (const char* key : {"min_gcp_distance_m", "min_gcp_distance_per_radius",
                            "min_hand_turn_deg"})
      if (v.contains(key)) {
        diversity[key] = v[key];
        v.erase(key);
      }
    v["physics_file"] = "";
  }
  if (j.contains("parameters") && j["parameters"].is_object())
    j["parameters"]["diversity"] = diversity;
  if (j.contains("grasps") && j["grasps"].is_array())
    for (nlohmann::json& g : j["grasps"]) {
      if (!g.is_object()) continue;
      if (!g.contains("preshape_joints")) g["preshape_joints"] = nlohmann::json::object();
      if (!g.contains("alpha_approach_rad") && g.contains("alpha_rad"))
        g["alpha_approach_rad"] = g["alpha_rad"];
      if (!g.contains("measures")) g["measures"] = params_to_json(CandidateMeasures{});
    }
  j["format_version"] = 3;
}

nlohmann::json read_plan_json(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError("read_plan: '" + path + "': cannot open file");
  nlohmann::json j;
  try {
    in >> j;
  } catch (const nlohmann::json::exception& e) {
    throw InputError("read_plan: '" + path + "': not valid JSON (" + e.what() + ")");
  }
  if (!j.is_object() || j.value("format", std::string()) != kFormat)
    throw InputError("read_plan: '" + path + "': not a cordgrasp plan (format != " + kFormat + ")");
  if (j.value("format_version", 0) == 1)
    throw InputError("read_plan: '" + path + "': format_version 1 (untyped parameters) is no "
                     "longer read; plan the object again");
  if (j.value("format_version", 0) == 2) upgrade_plan_from_version_2(&j);
  if (j.value("format_version", 0) != kFormatVersion)
    throw InputError("read_plan: '" + path + "': unsupported format_version " +
                     j.value("format_version", nlohmann::json(nullptr)).dump());
  // Keys that plans validated before P(held) lack: they were accepted by nudged trials.
  if (j.contains("validation") && j["validation"].is_object() &&
      j["validation"].contains("parameters") && j["validation"]["parameters"].is_object()) {
    nlohmann::json& v = j["validation"]["parameters"];
    const ValidationParams defaults;
    if (!v.contains("uncertainty")) v["uncertainty"] = params_to_json(defaults.uncertainty);
    if (!v.contains("min_hold_probability"))
      v["min_hold_probability"] = defaults.min_hold_probability;
    if (!v.contains("max_draws")) v["max_draws"] = defaults.max_draws;
  }
  // Plans written before the cord planner's fallback were planned without it.
  if (j.contains("parameters") && j["parameters"].is_object() &&
      !j["parameters"].contains("fallback_attempts"))
    j["parameters"]["fallback_attempts"] = 0;
  // A relative hand or object path naming a file beside the plan is taken from the plan's
  // folder (a plan moved with its files); else it stays (a shipped name, or from the cwd).
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  for (const char* input : {"hand", "object"}) {
    nlohmann::json* entry = j.contains("inputs") && j["inputs"].is_object() &&
                                    j["inputs"].contains(input) && j["inputs"][input].is_object()
                                ? &j["inputs"][input]
                                : nullptr;
    if (!entry || !entry->contains("path") || !(*entry)["path"].is_string()) continue;
    const std::filesystem::path recorded = (*entry)["path"].get<std::string>();
    if (recorded.is_relative() && !recorded.empty() &&
        std::filesystem::is_regular_file(folder / recorded))
      (*entry)["path"] = std::filesystem::absolute(folder / recorded).lexically_normal().string();
  }
  return j;
}

std::string plan_hand_path(const nlohmann::json& plan) {
  return plan.at("inputs").at("hand").at("path").get<std::string>();
}

std::string plan_object_path(const nlohmann::json& plan) {
  return plan.at("inputs").at("object").at("path").get<std::string>();
}

PlanDocument plan_from_json(const nlohmann::json& j, const HandModel& hand,
                            const std::string& source) {
  PlanDocument p;
  try {
    p.cordgrasp_version = j.value("cordgrasp_version", std::string());
    const auto& in_hand = j.at("inputs").at("hand");
    const auto& in_obj = j.at("inputs").at("object");
    p.hand_name = in_hand.at("name").get<std::string>();
    p.hand_path = in_hand.value("path", std::string());
    p.urdf_path = in_hand.value("urdf_path", std::string());
    p.object_path = in_obj.at("path").get<std::string>();
    p.object_name = in_obj.value("name", std::string());
    p.object_units = in_obj.value("units", std::string("m"));
    if (!in_obj.contains("scale") || !in_obj.at("scale").is_number())
      throw InputError(source + ": inputs.object.scale: " +
                       (in_obj.contains("scale") ? "not a number" : "missing"));
    p.object_scale = in_obj.at("scale").get<double>();
    if (!(std::isfinite(p.object_scale) && p.object_scale > 0.0))
      throw InputError(source + ": inputs.object.scale: " + format_number(p.object_scale) +
                       " is not finite and > 0");
    p.object_triangles = in_obj.value("triangles", 0);
    if (!j.contains("parameters")) throw InputError(source + ": parameters: missing");
    JsonReadArchive parameters(j.at("parameters"), source, "parameters");
    PlanParameters{&p}.Serialize(&parameters);
    parameters.reject_unknown_keys();
    p.stats = stats_from_json(j.value("stats", nlohmann::json::object()), source);
    p.interrupted = read_interrupted(j, source);
    p.stats.interrupted = !p.interrupted.empty();
    if (p.hand_name != hand.name)
      throw InputError(source + ": made for hand '" + p.hand_name + "', not '" + hand.name + "'");
    if (j.contains("validation")) {
      const auto& v = j.at("validation");
      JsonReadArchive top(v, source, "validation");  // an object, or InputError
      PlanValidation record;
      params_from_json(v.contains("parameters") ? v.at("parameters") : nlohmann::json(),
                       source, "validation.parameters", &record.params);
      {  // counts added in later versions keep their defaults in older plans
        const nlohmann::json stats_json = v.contains("stats") ? v.at("stats") : nlohmann::json();
        JsonReadArchive stats(stats_json, source, "validation.stats", MissingKey::kKeepDefault);
        record.stats.Serialize(&stats);
        stats.reject_unknown_keys();
      }
      for (const auto& item : v.items())
        if (item.key() != "parameters" && item.key() != "stats")
          throw InputError(source + ": validation: unknown key '" + item.key() + "'");
      p.validation = record;
    }
    if (!j.contains("grasps") || !j.at("grasps").is_array())
      throw InputError(source + ": grasps: " +
                       (j.contains("grasps") ? "expected a JSON array" : "missing"));
    for (const auto& g : j.at("grasps")) {
      Grasp grasp;
      const std::string where = source + ": grasps[" + std::to_string(p.grasps.size()) + "]";
      if (!g.is_object()) throw InputError(where + ": expected a JSON object");
      grasp.X_OB = pose_from_json(member(g, "hand_pose", where), where + ".hand_pose");
      grasp.X_OG = pose_from_json(member(g, "gcp_pose", where), where + ".gcp_pose");
      grasp.q = joints_from_json(hand, member(g, "joints", where), where + ".joints");
      grasp.q_preshape = joints_from_json(hand, member(g, "preshape_joints", where),
                                          where + ".preshape_joints");
      const nlohmann::json& contacts = array_member(g, "contacts", where);
      for (size_t k = 0; k < contacts.size(); ++k) {
        const nlohmann::json& c = contacts[k];
        const std::string at = where + ".contacts[" + std::to_string(k) + "]";
        Contact contact;
        const std::string link = string_member(c, "link", at);
        contact.link = find_link(hand, link);
        if (contact.link < 0)
          throw InputError(at + ".link: names link '" + link + "' that hand '" + hand.name +
                           "' does not have");
        contact.p_O = point_from_json(member(c, "point_m", at), at + ".point_m");
        contact.n_O = point_from_json(member(c, "normal", at), at + ".normal");
        grasp.contacts.push_back(contact);
      }
      grasp.force_closure = optional_bool(g, "force_closure", false, where);
      grasp.epsilon = optional_number(g, "epsilon", 0.0, where);
      grasp.alpha_rad = optional_number(g, "alpha_rad", 0.0, where);
      grasp.alpha_approach_rad = optional_number(g, "alpha_approach_rad", 0.0, where);
      params_from_json(member(g, "measures", where), source,
                       "grasps[" + std::to_string(p.grasps.size()) + "].measures",
                       &grasp.measures);
      if (g.contains("chi_m2") && !g["chi_m2"].is_null())
        grasp.chi_m2 = finite_number(g["chi_m2"], where + ".chi_m2");
      if (g.contains("region_rank") && !g["region_rank"].is_null()) {
        if (!g["region_rank"].is_number_integer())
          throw InputError(where + ".region_rank: not a whole number");
        grasp.region_rank = g["region_rank"].get<int>();
      }
      if (g.contains("region") && !g["region"].is_null()) {
        try {
          grasp.region = region_from_json(g["region"]);
        } catch (const InputError& e) {
          throw InputError(where + ".region: " + e.what());
        }
      }
      if (p.validation) {
        if (!g.contains("validation"))
          throw InputError(where + ".validation: missing (the plan is a validated one)");
        GraspValidation gv;
        params_from_json(g.at("validation"), source,
                         "grasps[" + std::to_string(p.grasps.size()) + "].validation", &gv);
        p.validation->grasps.push_back(gv);
      } else if (g.contains("validation")) {
        throw InputError(where + ".validation: given, but the plan has no top-level validation");
      }
      const auto t = g.value("timings_s", nlohmann::json::object());
      if (!t.is_object()) throw InputError(where + ".timings_s: expected a JSON object");
      grasp.times.exploration_s = optional_number(t, "exploration", 0.0, where + ".timings_s");
      grasp.times.finger_s = optional_number(t, "finger", 0.0, where + ".timings_s");
      grasp.times.quality_s = optional_number(t, "quality", 0.0, where + ".timings_s");
      p.grasps.push_back(std::move(grasp));
    }
  } catch (const nlohmann::json::exception& e) {
    throw InputError(source + ": malformed plan.json (" + e.what() + ")");
  }
  return p;
}

}  // namespace cordgrasp
