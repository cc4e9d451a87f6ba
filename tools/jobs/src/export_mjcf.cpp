#include "cordgrasp/jobs/export_mjcf.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <map>
#include <sstream>
#include <stdexcept>

#include "cordgrasp/core/atomic_file.h"
#include "cordgrasp/core/error.h"
#include "cordgrasp/core/kinematics.h"
#include "cordgrasp/jobs/sim_json.h"

namespace cordgrasp {
namespace {

namespace fs = std::filesystem;

/// Width given to a joint range with lower == upper [rad or m].
constexpr double kLockedRange = 1e-6;

/// Numbers as MJCF text: 10 significant digits (0.1 µm at 1 km).
std::string num(double v) {
  std::ostringstream s;
  s.precision(10);
  s << (std::abs(v) < 1e-15 ? 0.0 : v);
  return s.str();
}

std::string vec(const Eigen::Vector3d& v) {
  return num(v.x()) + " " + num(v.y()) + " " + num(v.z());
}

/// MuJoCo's quaternion order: w x y z.
std::string quat(const Eigen::Matrix3d& R) {
  const Eigen::Quaterniond q(R);
  return num(q.w()) + " " + num(q.x()) + " " + num(q.y()) + " " + num(q.z());
}

std::string pose_attrs(const Eigen::Isometry3d& X) {
  return " pos=\"" + vec(X.translation()) + "\" quat=\"" + quat(X.linear()) + "\"";
}

/// XML attribute text: &, <, > and " escaped.
std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

/// Binary STL bytes of `mesh` (float32, facet normals from the vertex order).
std::string stl_bytes(const Mesh& mesh) {
  std::string out(80, '\0');
  const std::uint32_t n = static_cast<std::uint32_t>(mesh.triangles.size());
  out.append(reinterpret_cast<const char*>(&n), 4);
  auto put = [&out](const Eigen::Vector3d& v) {
    const float f[3] = {static_cast<float>(v.x()), static_cast<float>(v.y()),
                        static_cast<float>(v.z())};
    out.append(reinterpret_cast<const char*>(f), sizeof(f));
  };
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.vertices[t[0]];
    const Eigen::Vector3d& b = mesh.vertices[t[1]];
    const Eigen::Vector3d& c = mesh.vertices[t[2]];
    const Eigen::Vector3d normal = (b - a).cross(c - a);
    put(normal.norm() > 0 ? Eigen::Vector3d(normal.normalized()) : Eigen::Vector3d::Zero());
    put(a);
    put(b);
    put(c);
    out.append(2, '\0');
  }
  return out;
}

bool is_prismatic(const Joint& j) { return j.type == JointType::kPrismatic; }

double effort_of(const Joint& j, const MjcfParams& p) {
  if (j.effort_limit > 0) return j.effort_limit;
  return is_prismatic(j) ? p.default_effort_N : p.default_effort_Nm;
}

/// Writes the hand's link bodies depth first; records the moving joints in MuJoCo's qpos order.
class HandWriter {
 public:
  HandWriter(const HandModel& hand, const MjcfParams& params,
             const std::map<const Mesh*, std::string>& mesh_names)
      : hand_(hand), params_(params), mesh_names_(mesh_names), children_(hand.links.size()) {
    for (size_t j = 0; j < hand.joints.size(); ++j)
      children_[hand.joints[j].parent_link].push_back(static_cast<int>(j));
  }

  void write_root(std::ostream& out, const Eigen::Isometry3d& X_OB) {
    const Link& root = hand_.links[hand_.root_link];
    out << "    <body name=\"" << MjcfNames::kHandTarget << "\" mocap=\"true\""
        << pose_attrs(X_OB) << "/>\n";
    out << "    <body name=\"" << escaped(root.name) << "\"" << pose_attrs(X_OB) << ">\n";
    out << "      <freejoint name=\"" << MjcfNames::kHandJoint << "\"/>\n";
    write_link_contents(out, hand_.root_link, "      ");
    out << "    </body>\n";
  }

  const std::vector<int>& qpos_joints() const { return qpos_joints_; }

 private:
  void write_link_contents(std::ostream& out, int link, const std::string& indent) {
    const Link& l = hand_.links[link];
    const Inertial& in = l.inertial;
    const Eigen::Matrix3d& I = in.inertia_kgm2;
    out << indent << "<inertial pos=\"" << vec(in.com_m) << "\" mass=\"" << num(in.mass_kg)
        << "\" fullinertia=\"" << num(I(0, 0)) << " " << num(I(1, 1)) << " " << num(I(2, 2))
        << " " << num(I(0, 1)) << " " << num(I(0, 2)) << " " << num(I(1, 2)) << "\"/>\n";
    for (size_t g = 0; g < l.collisions.size(); ++g) write_geom(out, l, l.collisions[g], indent);
    if (link == hand_.gcp.link)
      out << indent << "<site name=\"" << MjcfNames::kGcpSite << "\""
          << pose_attrs(hand_.gcp.X_LG) << " size=\"" << num(params_.gcp_site_size_m)
          << "\"/>\n";
    for (int j : children_[link]) {
      const Joint& joint = hand_.joints[j];
      out << indent << "<body name=\"" << escaped(hand_.links[joint.child_link].name) << "\""
          << pose_attrs(joint.X_PJ) << ">\n";
      if (joint.is_moving()) {
        const bool slide = is_prismatic(joint);
        const double armature = slide ? params_.armature_kg : params_.armature_kgm2;
        const double kp = effort_of(joint, params_) / (slide ? params_.squeeze_m
                                                             : params_.squeeze_rad);
        out << indent << "  <joint name=\"" << escaped(joint.name) << "\" type=\""
            << (slide ? "slide" : "hinge") << "\" axis=\"" << vec(joint.axis) << "\"";
        if (joint.type != JointType::kContinuous) {
          // MuJoCo refuses an empty range: a joint locked by lower == upper gets kLockedRange.
          const double upper = std::max(joint.upper, joint.lower + kLockedRange);
          out << " limited=\"true\" range=\"" << num(joint.lower) << " " << num(upper)
              << "\"";
        }
        out << " armature=\"" << num(armature) << "\" damping=\""
            << num(2.0 * std::sqrt(kp * armature)) << "\"/>\n";
        qpos_joints_.push_back(j);
      }
      write_link_contents(out, joint.child_link, indent + "  ");
      out << indent << "</body>\n";
    }
  }

  void write_geom(std::ostream& out, const Link& l, const Geometry& g, const std::string& indent) {
    out << indent << "<geom class=\"hand\"" << pose_attrs(g.X_LG);
    switch (g.kind) {
      case Geometry::Kind::kBox:
        out << " type=\"box\" size=\"" << vec(0.5 * g.box_size_m) << "\"";
        break;
      case Geometry::Kind::kCylinder:
        out << " type=\"cylinder\" size=\"" << num(g.radius_m) << " " << num(0.5 * g.length_m)
            << "\"";
        break;
      case Geometry::Kind::kSphere:
        out << " type=\"sphere\" size=\"" << num(g.radius_m) << "\"";
        break;
      case Geometry::Kind::kMesh:
        out << " type=\"mesh\" mesh=\"" << escaped(mesh_names_.at(g.mesh.get())) << "\"";
        break;
    }
    (void)l;
    out << "/>\n";
  }

  const HandModel& hand_;
  const MjcfParams& params_;
  const std::map<const Mesh*, std::string>& mesh_names_;
  std::vector<std::vector<int>> children_;
  std::vector<int> qpos_joints_;
};

/// The actor entry driving joint j (its direction_speed: sign = closing direction, magnitude =
/// relative speed); 0: no actor.
double actor_speed(const HandModel& hand, int j) {
  for (const Actor& actor : hand.actors)
    for (const Actor::Entry& e : actor.joints)
      if (e.joint == j && e.direction_speed != 0.0) return e.direction_speed;
  return 0.0;
}

std::string joined(const Eigen::VectorXd& v) {
  std::string s;
  for (int i = 0; i < v.size(); ++i) s += (i ? " " : "") + num(v[i]);
  return s;
}

}  // namespace

std::vector<std::string> write_mjcf_scene(
    const std::string& path, const HandModel& hand, const std::vector<Grasp>& grasps,
    const ContactModel& contact, const std::vector<std::vector<Eigen::Vector3d>>& parts,
    const MjcfParams& params, const std::vector<BoundedClose>& closes, const SimParams& sim) {
  if (!closes.empty() && closes.size() != grasps.size())
    throw std::invalid_argument("write_mjcf_scene: " + std::to_string(closes.size()) +
                                " bounded closes for " + std::to_string(grasps.size()) +
                                " grasps");
  std::vector<std::string> files{path};
  const fs::path out_path(path);
  const std::string mesh_dir_name = out_path.stem().string() + "_meshes";
  const fs::path mesh_dir = out_path.parent_path() / mesh_dir_name;
  std::error_code ec;
  fs::create_directories(mesh_dir, ec);
  if (ec) throw InputError("export: cannot create '" + mesh_dir.string() + "': " + ec.message());

  // Hand meshes: one STL per distinct collision mesh, named after the first link using it.
  std::map<const Mesh*, std::string> mesh_names;
  std::ostringstream assets;
  for (const Link& l : hand.links)
    for (const Geometry& g : l.collisions) {
      if (g.kind != Geometry::Kind::kMesh || !g.mesh || mesh_names.count(g.mesh.get())) continue;
      const std::string name = l.name + "_" + std::to_string(mesh_names.size());
      mesh_names[g.mesh.get()] = name;
      const std::string file = name + ".stl";
      write_file_atomically((mesh_dir / file).string(), stl_bytes(*g.mesh));
      files.push_back((mesh_dir / file).string());
      assets << "    <mesh name=\"" << escaped(name) << "\" file=\"" << escaped(file) << "\"/>\n";
    }
  for (size_t k = 0; k < parts.size(); ++k) {
    assets << "    <mesh name=\"object_part_" << k << "\" vertex=\"";
    for (size_t i = 0; i < parts[k].size(); ++i) assets << (i ? " " : "") << vec(parts[k][i]);
    assets << "\"/>\n";
  }

  const Eigen::Isometry3d X_OB0 = grasps.empty() ? Eigen::Isometry3d::Identity() : grasps[0].X_OB;
  HandWriter writer(hand, params, mesh_names);
  std::ostringstream bodies;
  writer.write_root(bodies, X_OB0);

  const double mu = contact.mu;
  const double torsion = mu * contact.soft_finger_radius_m;
  std::ostringstream x;
  x << "<!-- Written by cordgrasp export: hand " << escaped(hand.name)
    << ", one keyframe per planned grasp; world = object frame (docs/export.md). -->\n";
  x << "<mujoco model=\"" << escaped(hand.name) << "\">\n";
  x << "  <compiler angle=\"radian\" meshdir=\"" << escaped(mesh_dir_name)
    << "\" inertiafromgeom=\"auto\" balanceinertia=\"true\" boundmass=\"1e-6\""
       " boundinertia=\"1e-12\"/>\n";
  x << "  <size nuser_actuator=\"2\"/>\n";
  x << "  <option timestep=\"" << num(params.time_step_s)
    << "\" gravity=\"0 0 -9.81\" cone=\"elliptic\" impratio=\"10\"/>\n";
  x << "  <default>\n";
  x << "    <default class=\"hand\"><geom contype=\"2\" conaffinity=\"1\" condim=\"3\" friction=\""
    << num(mu) << " " << num(torsion) << " 0.0001\" rgba=\"0.6 0.6 0.65 1\"/></default>\n";
  x << "    <default class=\"object\"><geom contype=\"1\" conaffinity=\"2\" condim=\""
    << (torsion > 0 ? 4 : 3) << "\" friction=\"" << num(mu) << " " << num(torsion)
    << " 0.0001\" density=\"" << num(params.density_kgm3)
    << "\" rgba=\"0.8 0.5 0.3 1\"/></default>\n";
  x << "  </default>\n";
  x << "  <asset>\n" << assets.str() << "  </asset>\n";
  x << "  <worldbody>\n" << bodies.str();
  x << "    <body name=\"" << MjcfNames::kObjectBody << "\">\n";
  x << "      <freejoint name=\"" << MjcfNames::kObjectJoint << "\"/>\n";
  for (size_t k = 0; k < parts.size(); ++k)
    x << "      <geom class=\"object\" type=\"mesh\" mesh=\"object_part_" << k << "\"/>\n";
  x << "    </body>\n  </worldbody>\n";

  // Couplings: q_mimic = offset + multiplier · q_master.
  std::ostringstream eq;
  for (const Joint& j : hand.joints)
    if (j.is_moving() && j.mimic)
      eq << "    <joint joint1=\"" << escaped(j.name) << "\" joint2=\""
         << escaped(hand.joints[j.mimic->master_joint].name) << "\" polycoef=\""
         << num(j.mimic->offset) << " " << num(j.mimic->multiplier) << " 0 0 0\"/>\n";
  x << "  <equality>\n    <weld body1=\"" << MjcfNames::kHandTarget << "\" body2=\""
    << escaped(hand.links[hand.root_link].name) << "\" solref=\"" << num(params.weld_time_s)
    << " 1\"/>\n"
    << eq.str() << "  </equality>\n";

  // Position servos on the joints a hand drives (not the mimic ones).
  std::vector<int> actuated;
  x << "  <actuator>\n";
  for (int j : writer.qpos_joints()) {
    const Joint& joint = hand.joints[j];
    if (joint.mimic) continue;
    actuated.push_back(j);
    const double effort = effort_of(joint, params);
    const double speed = actor_speed(hand, j);
    const double kp = effort / (is_prismatic(joint) ? params.squeeze_m : params.squeeze_rad);
    x << "    <position name=\"" << escaped(joint.name) << "\" joint=\"" << escaped(joint.name)
      << "\" kp=\"" << num(kp) << "\" forcelimited=\"true\" forcerange=\"" << num(-effort) << " "
      << num(effort) << "\" user=\"" << (speed > 0 ? 1 : speed < 0 ? -1 : 0) << " "
      << num(std::abs(speed)) << "\"/>\n";
  }
  x << "  </actuator>\n";

  if (!grasps.empty()) {
    x << "  <keyframe>\n";
    for (size_t k = 0; k < grasps.size(); ++k) {
      const Grasp& g = grasps[k];
      const Eigen::VectorXd& q = g.q;  // as planned (the couplings may be off by the closing)
      const size_t nj = writer.qpos_joints().size();
      Eigen::VectorXd qpos(7 + nj + 7);
      const Eigen::Quaterniond r(g.X_OB.linear());
      qpos.head(7) << g.X_OB.translation(), r.w(), r.x(), r.y(), r.z();
      for (size_t i = 0; i < nj; ++i) qpos[7 + i] = q[writer.qpos_joints()[i]];
      qpos.tail(7) << 0, 0, 0, 1, 0, 0, 0;
      Eigen::VectorXd ctrl(actuated.size());
      for (size_t i = 0; i < actuated.size(); ++i) ctrl[i] = q[actuated[i]];
      x << "    <key name=\"" << MjcfNames::keyframe(static_cast<int>(k)) << "\" qpos=\""
        << joined(qpos) << "\" mpos=\"" << vec(g.X_OB.translation()) << "\" mquat=\""
        << quat(g.X_OB.linear()) << "\" ctrl=\"" << joined(ctrl) << "\"/>\n";
    }
    x << "  </keyframe>\n";
  }
  if (!closes.empty()) {
    // Each grasp's bounded close (docs/physics.md §3a) as Bullet runs it: the hand joints at
    // the reach start (qpos order), per actuator the squeeze targets and effort limits.
    const auto per_actuator = [&](const Eigen::VectorXd& v) {
      Eigen::VectorXd out(static_cast<Eigen::Index>(actuated.size()));
      for (size_t i = 0; i < actuated.size(); ++i) out[i] = v[actuated[i]];
      return out;
    };
    const auto numeric = [&](size_t k, const char* what, const Eigen::VectorXd& v) {
      x << "    <numeric name=\"" << MjcfNames::close_numeric(static_cast<int>(k), what)
        << "\" size=\"" << v.size() << "\" data=\"" << joined(v) << "\"/>\n";
    };
    x << "  <custom>\n";
    for (size_t k = 0; k < closes.size(); ++k) {
      const BoundedClose& c = closes[k];
      Eigen::VectorXd start(static_cast<Eigen::Index>(writer.qpos_joints().size()));
      for (size_t i = 0; i < writer.qpos_joints().size(); ++i)
        start[i] = c.q_start[writer.qpos_joints()[i]];
      numeric(k, MjcfNames::kStart, start);
      numeric(k, MjcfNames::kSqueeze, per_actuator(c.q_squeeze));
      numeric(k, MjcfNames::kEffort, per_actuator(c.effort));
      numeric(k, MjcfNames::kHoldEffort, per_actuator(c.hold_effort));
      numeric(k, MjcfNames::kReachTime, Eigen::VectorXd::Constant(1, c.reach_time_s));
    }
    // The physics settings' numbers (top level; nested blocks, texts and unset ones skipped).
    const nlohmann::json settings = sim_params_to_json(sim);
    for (const auto& [field, value] : settings.items()) {
      if (!value.is_number() && !value.is_boolean()) continue;
      const double v = value.is_boolean() ? (value.get<bool>() ? 1.0 : 0.0) : value.get<double>();
      x << "    <numeric name=\"" << MjcfNames::sim_numeric(field) << "\" size=\"1\" data=\""
        << num(v) << "\"/>\n";
    }
    x << "  </custom>\n";
  }
  x << "</mujoco>\n";
  write_file_atomically(path, x.str());
  return files;
}

}  // namespace cordgrasp
