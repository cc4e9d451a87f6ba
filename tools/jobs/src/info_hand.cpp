// Hand part of `cordgrasp info`.
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/kinematics.h"
#include "cordgrasp/core/palm_width.h"
#include "cordgrasp/jobs/info.h"
#include "json_util.h"

namespace cordgrasp {
namespace {

const char* type_name(JointType t) {
  switch (t) {
    case JointType::kFixed:
      return "fixed";
    case JointType::kRevolute:
      return "revolute";
    case JointType::kContinuous:
      return "continuous";
    case JointType::kPrismatic:
      return "prismatic";
  }
  return "?";
}

const char* kind_name(Geometry::Kind k) {
  switch (k) {
    case Geometry::Kind::kBox:
      return "box";
    case Geometry::Kind::kCylinder:
      return "cylinder";
    case Geometry::Kind::kSphere:
      return "sphere";
    case Geometry::Kind::kMesh:
      return "mesh";
  }
  return "?";
}

/// A limit as JSON: null for ±infinity (continuous joints), which JSON cannot hold.
nlohmann::json limit_json(double v) { return std::isfinite(v) ? nlohmann::json(v) : nullptr; }

nlohmann::json geometry_json(const std::vector<Geometry>& geometry) {
  nlohmann::json out = nlohmann::json::array();
  for (const Geometry& g : geometry) {
    nlohmann::json j;
    j["kind"] = kind_name(g.kind);
    if (g.kind == Geometry::Kind::kMesh) {
      j["mesh"] = g.mesh_path;
      j["triangles"] = g.mesh ? g.mesh->triangles.size() : 0;
    }
    out.push_back(j);
  }
  return out;
}

}  // namespace

nlohmann::json hand_info_json(const std::string& name_or_path,
                              const HandLoadOptions& options) {
  const HandModel hand = load_hand(name_or_path, options);
  const Eigen::VectorXd q = apply_couplings(hand, hand.preshape);
  const auto X_WL = link_poses(hand, q);

  nlohmann::json j;
  j["name"] = hand.name;
  j["description_path"] = hand.description_path;
  j["urdf_path"] = hand.urdf_path;
  j["root_link"] = hand.links[hand.root_link].name;

  nlohmann::json links = nlohmann::json::array();
  nlohmann::json substituted = nlohmann::json::array();
  for (const Link& l : hand.links) {
    nlohmann::json lj;
    lj["name"] = l.name;
    lj["parent_joint"] = l.parent_joint >= 0 ? nlohmann::json(hand.joints[l.parent_joint].name)
                                             : nlohmann::json(nullptr);
    lj["mass_kg"] = l.inertial.mass_kg;
    lj["com_m"] = to_json(l.inertial.com_m);
    lj["inertia_diagonal_kgm2"] = to_json(l.inertial.inertia_kgm2.diagonal());
    lj["inertial_substituted"] = l.inertial.substituted;
    lj["collisions"] = geometry_json(l.collisions);
    lj["visuals"] = geometry_json(l.visuals);
    lj["position_in_preshape_m"] = to_json(X_WL[&l - hand.links.data()].translation());
    links.push_back(lj);
    if (l.inertial.substituted) substituted.push_back(l.name);
  }
  j["links"] = links;
  j["substituted_inertials"] = substituted;

  std::map<std::string, int> counts = {
      {"fixed", 0}, {"revolute", 0}, {"continuous", 0}, {"prismatic", 0}, {"mimic", 0}};
  nlohmann::json joints = nlohmann::json::array();
  nlohmann::json preshape = nlohmann::json::object();
  for (size_t i = 0; i < hand.joints.size(); ++i) {
    const Joint& jt = hand.joints[i];
    ++counts[type_name(jt.type)];
    nlohmann::json jj;
    jj["name"] = jt.name;
    jj["type"] = type_name(jt.type);
    jj["parent"] = hand.links[jt.parent_link].name;
    jj["child"] = hand.links[jt.child_link].name;
    if (jt.is_moving()) {
      jj["axis"] = to_json(jt.axis);
      jj["lower"] = limit_json(jt.lower);
      jj["upper"] = limit_json(jt.upper);
      jj["effort_limit"] = jt.effort_limit;
      jj["velocity_limit"] = jt.velocity_limit;
      jj["preshape"] = q[static_cast<Eigen::Index>(i)];
      preshape[jt.name] = q[static_cast<Eigen::Index>(i)];
    }
    if (jt.mimic) {
      ++counts["mimic"];
      jj["mimic"] = {{"master", hand.joints[jt.mimic->master_joint].name},
                     {"multiplier", jt.mimic->multiplier},
                     {"offset", jt.mimic->offset}};
    }
    joints.push_back(jj);
  }
  j["joints"] = joints;
  j["joint_counts"] = counts;
  j["joint_counts"]["total"] = hand.joints.size();
  j["link_count"] = hand.links.size();
  j["dof"] = degrees_of_freedom(hand);
  j["mass_kg"] = total_mass(hand);
  j["preshape"] = preshape;

  const Eigen::Isometry3d X_WG = gcp_pose(hand, X_WL);
  j["gcp"] = {{"link", hand.links[hand.gcp.link].name},
              {"xyz_in_link_m", to_json(hand.gcp.X_LG.translation())},
              {"position_in_preshape_m", to_json(X_WG.translation())},
              {"x_axis", to_json(X_WG.linear().col(0))},
              {"z_axis", to_json(X_WG.linear().col(2))}};
  j["gcp"]["frame_note"] = "preshape pose in the root link's frame; +z is the approach direction";

  nlohmann::json actors = nlohmann::json::array();
  for (const Actor& a : hand.actors) {
    nlohmann::json aj;
    aj["name"] = a.name;
    aj["joints"] = nlohmann::json::array();
    for (const auto& e : a.joints)
      aj["joints"].push_back({{"joint", hand.joints[e.joint].name}, {"speed", e.direction_speed}});
    actors.push_back(aj);
  }
  j["actors"] = actors;
  nlohmann::json thumb = nlohmann::json::array();
  for (int l : hand.thumb_links) thumb.push_back(hand.links[l].name);
  j["thumb_links"] = thumb;
  const double measured = measure_palm_width(hand);
  j["palm_width_measured_m"] = measured;
  j["palm_width_m"] = hand.palm_width_m ? *hand.palm_width_m : measured;
  j["palm_width_from_description"] = hand.palm_width_m.has_value();
  return j;
}

void print_hand_info(const nlohmann::json& j) {
  std::ostringstream out;
  out << std::setprecision(4);
  const auto& c = j["joint_counts"];
  out << "hand       " << j["name"].get<std::string>() << "  ("
      << j["description_path"].get<std::string>() << ")\n"
      << "urdf       " << j["urdf_path"].get<std::string>() << '\n'
      << "links      " << j["link_count"] << "  (root '" << j["root_link"].get<std::string>()
      << "')\n"
      << "joints     " << c["total"] << "  (" << c["revolute"] << " revolute, " << c["prismatic"]
      << " prismatic, " << c["continuous"] << " continuous, " << c["fixed"] << " fixed; "
      << c["mimic"] << " coupled)\n"
      << "DOF        " << j["dof"] << '\n'
      << "mass       " << j["mass_kg"].get<double>() << " kg\n"
      << "palm width " << j["palm_width_m"].get<double>() << " m  ("
      << (j["palm_width_from_description"].get<bool>()
              ? "from the description; measured " +
                    std::to_string(j["palm_width_measured_m"].get<double>()) + " m)\n"
              : std::string("measured in preshape, docs/algorithm.md §4)\n"))
      << "GCP        link '" << j["gcp"]["link"].get<std::string>() << "', in preshape at "
      << vec_text(j["gcp"]["position_in_preshape_m"]) << " m, approach +z "
      << vec_text(j["gcp"]["z_axis"]) << '\n';
  out << "joints (moving):\n";
  out << "  " << std::left << std::setw(28) << "name" << std::setw(11) << "type" << std::right
      << std::setw(9) << "lower" << std::setw(9) << "upper" << std::setw(10) << "preshape"
      << "  coupling\n";
  for (const auto& jt : j["joints"]) {
    if (jt["type"] == "fixed") continue;
    auto num = [](const nlohmann::json& v) {
      std::ostringstream s;
      s << std::setprecision(4);
      if (v.is_null())
        s << "inf";
      else
        s << v.get<double>();
      return s.str();
    };
    out << "  " << std::left << std::setw(28) << jt["name"].get<std::string>() << std::setw(11)
        << jt["type"].get<std::string>() << std::right << std::setw(9) << num(jt["lower"])
        << std::setw(9) << num(jt["upper"]) << std::setw(10) << num(jt["preshape"]);
    if (jt.contains("mimic"))
      out << "  = " << jt["mimic"]["multiplier"].get<double>() << " x '"
          << jt["mimic"]["master"].get<std::string>() << "'";
    out << '\n';
  }
  out << "actors:\n";
  for (const auto& a : j["actors"]) {
    out << "  " << a["name"].get<std::string>() << ":";
    for (const auto& e : a["joints"])
      out << " '" << e["joint"].get<std::string>() << "' " << std::showpos
          << e["speed"].get<double>() << std::noshowpos;
    out << '\n';
  }
  out << "thumb      ";
  for (const auto& t : j["thumb_links"]) out << "'" << t.get<std::string>() << "' ";
  out << '\n' << "inertials  ";
  if (j["substituted_inertials"].empty())
    out << "all from the URDF\n";
  else
    out << j["substituted_inertials"].size()
        << " missing or placeholder, substituted (see the warning)\n";
  std::cout << out.str();
}

}  // namespace cordgrasp
