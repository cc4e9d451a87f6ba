// URDF import: urdfdom's model → HandModel links and joints (kinematics, geometry, inertials).
#include "urdf_import.h"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>
#include <tuple>
#include <vector>

#include "cordgrasp/core/kinematics.h"
#include "cordgrasp/core/mesh_io.h"
#include "find_ros_package.h"
#include "hand_load_common.h"
#include "substitute_inertial.h"

namespace fs = std::filesystem;

namespace cordgrasp::hand_load {
namespace {

// ---------------------------------------------------------------------------------------------
// urdfdom: parse with errors captured instead of printed

class CapturingOutputHandler : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR && first_error.empty())
      first_error = text;
  }
  std::string first_error;
};

urdf::ModelInterfaceSharedPtr parse_urdf(const std::string& urdf_path) {
  std::ifstream in(urdf_path);
  if (!in) fail(urdf_path, "cannot read the URDF");
  std::stringstream text;
  text << in.rdbuf();
  static std::mutex mutex;
  std::lock_guard<std::mutex> lock(mutex);
  CapturingOutputHandler handler;
  console_bridge::useOutputHandler(&handler);
  urdf::ModelInterfaceSharedPtr model;
  try {
    model = urdf::parseURDF(text.str());
  } catch (const std::exception& e) {
    handler.first_error = e.what();
  }
  console_bridge::restorePreviousOutputHandler();
  // urdfdom returns a model even when an element failed to parse and was dropped with the
  // rest of its link (a value such as "nan": a link without its geometry): an error either way.
  if (!model || !handler.first_error.empty()) {
    std::string why = handler.first_error.empty() ? "malformed URDF" : handler.first_error;
    while (!why.empty() && (why.back() == '\n' || why.back() == ' ')) why.pop_back();
    fail(urdf_path, "URDF parse error: " + why);
  }
  // A link owns its children (shared_ptr): joints closing a cycle, which import_urdf refuses,
  // would keep the model alive forever. The pointer returned drops those links first.
  return urdf::ModelInterfaceSharedPtr(model.get(), [model](urdf::ModelInterface* m) mutable {
    for (auto& name_link : m->links_) name_link.second->child_links.clear();
    model.reset();
  });
}

Eigen::Isometry3d to_isometry(const urdf::Pose& pose) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  const auto& r = pose.rotation;
  X.linear() = Eigen::Quaterniond(r.w, r.x, r.y, r.z).normalized().toRotationMatrix();
  X.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  return X;
}

// ---------------------------------------------------------------------------------------------
// Geometry

/// Meshes shared between links within one load (same file and scale).
using MeshCache =
    std::map<std::tuple<std::string, double, double, double>, std::shared_ptr<const Mesh>>;

/// Path of a URDF mesh filename: relative to the URDF, absolute, file://PATH, or
/// package://NAME/REST resolved with find_ros_package.
std::string resolve_mesh_path(const std::string& urdf_path, const std::string& link,
                              const std::string& filename, const HandLoadOptions& options) {
  std::string name = filename;
  if (name.rfind("file://", 0) == 0) name = name.substr(7);
  fs::path p(name);
  if (name.rfind("package://", 0) == 0) {
    const std::string rest = name.substr(10);
    const size_t slash = rest.find('/');
    const std::string package = rest.substr(0, slash);
    if (package.empty() || slash == std::string::npos || slash + 1 == rest.size())
      fail(urdf_path, "link " + in_quotes(link) + " mesh " + in_quotes(filename) +
                          ": a package:// URI must read package://NAME/PATH");
    const std::string dir = find_ros_package(package, options.package_paths);
    if (dir.empty())
      fail(urdf_path, "link " + in_quotes(link) + " mesh " + in_quotes(filename) +
                          ": ROS package " + in_quotes(package) + " not found (searched " +
                          ros_package_search_summary(options.package_paths) + ")");
    p = fs::path(dir) / rest.substr(slash + 1);
  }
  if (p.is_relative()) p = fs::path(urdf_path).parent_path() / p;
  p = p.lexically_normal();
  if (!fs::is_regular_file(p))
    fail(urdf_path, "link " + in_quotes(link) + ": mesh file " + in_quotes(filename) +
                        " not found (looked for " + in_quotes(p.string()) + ")");
  return p.string();
}

Geometry convert_geometry(const urdf::GeometrySharedPtr& g, const urdf::Pose& origin,
                          const std::string& urdf_path, const std::string& link,
                          const HandLoadOptions& options, MeshCache& cache) {
  if (!g) fail(urdf_path, "link " + in_quotes(link) + " has a collision/visual without geometry");
  Geometry out;
  out.X_LG = to_isometry(origin);
  auto positive = [&](double v, const char* what) {
    if (!(std::isfinite(v) && v > 0.0))
      fail(urdf_path,
           "link " + in_quotes(link) + ": " + what + " must be > 0, got " + std::to_string(v));
  };
  switch (g->type) {
    case urdf::Geometry::BOX: {
      const auto& box = static_cast<const urdf::Box&>(*g);
      out.kind = Geometry::Kind::kBox;
      out.box_size_m = Eigen::Vector3d(box.dim.x, box.dim.y, box.dim.z);
      positive(box.dim.x, "box size x");
      positive(box.dim.y, "box size y");
      positive(box.dim.z, "box size z");
      break;
    }
    case urdf::Geometry::CYLINDER: {
      const auto& cyl = static_cast<const urdf::Cylinder&>(*g);
      out.kind = Geometry::Kind::kCylinder;
      out.radius_m = cyl.radius;
      out.length_m = cyl.length;
      positive(cyl.radius, "cylinder radius");
      positive(cyl.length, "cylinder length");
      break;
    }
    case urdf::Geometry::SPHERE: {
      const auto& sph = static_cast<const urdf::Sphere&>(*g);
      out.kind = Geometry::Kind::kSphere;
      out.radius_m = sph.radius;
      positive(sph.radius, "sphere radius");
      break;
    }
    case urdf::Geometry::MESH: {
      const auto& m = static_cast<const urdf::Mesh&>(*g);
      out.kind = Geometry::Kind::kMesh;
      out.mesh_path = resolve_mesh_path(urdf_path, link, m.filename, options);
      const Eigen::Vector3d scale(m.scale.x, m.scale.y, m.scale.z);
      if (!scale.allFinite() || scale.cwiseAbs().minCoeff() == 0.0)
        fail(urdf_path, "link " + in_quotes(link) + ": mesh " + in_quotes(m.filename) +
                            " has a zero or invalid scale");
      const auto key = std::make_tuple(out.mesh_path, scale.x(), scale.y(), scale.z());
      auto it = cache.find(key);
      if (it == cache.end()) {
        Mesh mesh;
        try {
          mesh = load_mesh(out.mesh_path);
        } catch (const InputError& e) {
          fail(urdf_path, "link " + in_quotes(link) + ": " + e.what());
        }
        for (auto& v : mesh.vertices) v = v.cwiseProduct(scale);
        it = cache.emplace(key, std::make_shared<const Mesh>(std::move(mesh))).first;
      }
      out.mesh = it->second;
      break;
    }
    default:
      fail(urdf_path, "link " + in_quotes(link) + ": unsupported geometry type");
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// Links and joints

Eigen::Vector4d material_rgba(const urdf::Visual& vis, const urdf::ModelInterface& model) {
  const Eigen::Vector4d kDefault(0.7, 0.7, 0.7, 1.0);
  if (!vis.material) return kDefault;
  const auto& c = vis.material->color;
  // urdfdom leaves a name-only reference black (0,0,0,1); resolve it against global materials.
  const bool name_only = c.r == 0.0f && c.g == 0.0f && c.b == 0.0f && c.a == 1.0f;
  if (name_only) {
    const auto global =
        vis.material_name.empty() ? nullptr : model.getMaterial(vis.material_name);
    if (!global) return kDefault;  // e.g. a texture-only material
    const auto& gc = global->color;
    return Eigen::Vector4d(gc.r, gc.g, gc.b, gc.a);
  }
  return Eigen::Vector4d(c.r, c.g, c.b, c.a);
}

/// The HandModel link of a URDF link: geometry, colours, declared or substituted inertial.
Link convert_link(const urdf::Link& ul, int parent_joint, const urdf::ModelInterface& model,
                  const std::string& urdf_path, const HandLoadOptions& options, MeshCache& cache) {
  Link link;
  link.name = ul.name;
  link.parent_joint = parent_joint;
  for (const auto& c : ul.collision_array)
    link.collisions.push_back(
        convert_geometry(c->geometry, c->origin, urdf_path, ul.name, options, cache));
  for (const auto& v : ul.visual_array) {
    Geometry g = convert_geometry(v->geometry, v->origin, urdf_path, ul.name, options, cache);
    g.rgba = material_rgba(*v, model);
    link.visuals.push_back(std::move(g));
  }
  const bool declared = static_cast<bool>(ul.inertial);
  if (declared) {
    const urdf::Inertial& ui = *ul.inertial;
    const Eigen::Isometry3d X_LI = to_isometry(ui.origin);
    Eigen::Matrix3d I;
    I << ui.ixx, ui.ixy, ui.ixz, ui.ixy, ui.iyy, ui.iyz, ui.ixz, ui.iyz, ui.izz;
    link.inertial.mass_kg = ui.mass;
    link.inertial.com_m = X_LI.translation();
    link.inertial.inertia_kgm2 = X_LI.linear() * I * X_LI.linear().transpose();
  }
  substitute_inertial_if_needed(link, declared);
  return link;
}

/// The HandModel joint of a URDF joint (child_link and the mimic's master left for the caller);
/// `mimic_master` receives the name of the joint a moving joint mimics.
Joint convert_joint(const urdf::Joint& uj, int parent_link, const std::string& urdf_path,
                    std::optional<std::string>& mimic_master) {
  Joint joint;
  joint.name = uj.name;
  joint.parent_link = parent_link;
  joint.X_PJ = to_isometry(uj.parent_to_joint_origin_transform);
  const auto lim = uj.limits;
  switch (uj.type) {
    case urdf::Joint::FIXED:
      joint.type = JointType::kFixed;
      break;
    case urdf::Joint::REVOLUTE:
      joint.type = JointType::kRevolute;
      break;
    case urdf::Joint::CONTINUOUS:
      joint.type = JointType::kContinuous;
      break;
    case urdf::Joint::PRISMATIC:
      joint.type = JointType::kPrismatic;
      break;
    default:
      fail(urdf_path, "joint " + in_quotes(uj.name) +
                          ": unsupported type (only fixed, revolute, continuous, prismatic)");
  }
  if (joint.is_moving()) {
    joint.axis = Eigen::Vector3d(uj.axis.x, uj.axis.y, uj.axis.z);
    if (!joint.axis.allFinite() || joint.axis.norm() < 1e-12)
      fail(urdf_path, "joint " + in_quotes(uj.name) + " has a zero axis");
    joint.axis.normalize();
  }
  if (joint.type == JointType::kRevolute || joint.type == JointType::kPrismatic) {
    if (!lim) fail(urdf_path, "joint " + in_quotes(uj.name) + " has no <limit>");
    joint.lower = lim->lower;
    joint.upper = lim->upper;
    if (!std::isfinite(joint.lower) || !std::isfinite(joint.upper))
      fail(urdf_path, "joint " + in_quotes(uj.name) + " has non-finite limits");
    if (joint.lower > joint.upper) {
      std::ostringstream s;
      s << "joint " << in_quotes(uj.name) << " has inverted limits: lower " << joint.lower
        << " > upper " << joint.upper;
      fail(urdf_path, s.str());
    }
  } else if (joint.type == JointType::kContinuous) {
    joint.lower = -std::numeric_limits<double>::infinity();
    joint.upper = std::numeric_limits<double>::infinity();
  }
  if (lim && joint.is_moving()) {
    // Negative values (e.g. Simox "-1") mean "unlimited": stored as 0 = not given.
    joint.effort_limit = std::max(0.0, lim->effort);
    joint.velocity_limit = std::max(0.0, lim->velocity);
  }
  if (uj.mimic && joint.is_moving()) {
    Mimic m;
    m.multiplier = uj.mimic->multiplier;
    m.offset = uj.mimic->offset;
    joint.mimic = m;
    mimic_master = uj.mimic->joint_name;
  }
  return joint;
}

/// "'a' -> 'b' -> ..." for error messages.
std::string joint_list(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : " -> ") + in_quotes(n);
  return out;
}

}  // namespace

HandModel import_urdf(const std::string& urdf_path, const HandLoadOptions& options) {
  const urdf::ModelInterfaceSharedPtr model = parse_urdf(urdf_path);
  const urdf::LinkConstSharedPtr root = model->getRoot();
  if (!root) fail(urdf_path, "URDF has no root link");

  HandModel hand;
  hand.urdf_path = urdf_path;
  MeshCache cache;
  std::map<std::string, std::string> mimic_master;  // joint -> master name

  // Depth-first from the root, as a loop over an explicit stack (the depth is the URDF's to
  // choose): a joint's parent link always precedes it. urdfdom accepts joints that close a
  // cycle or give a link a second parent; both are caught by the set of links entered so far.
  struct Frame {
    const urdf::Link* link;
    int link_index;
    size_t next_joint = 0;
  };
  std::map<std::string, int> entered;  // link name -> index of the Frame that entered it
  std::vector<Frame> stack;
  std::vector<std::string> path_joints;  // joint into stack[i + 1], for cycle messages
  hand.root_link = 0;
  hand.links.push_back(convert_link(*root, -1, *model, urdf_path, options, cache));
  entered[root->name] = 0;
  stack.push_back({root.get(), 0});
  while (!stack.empty()) {
    Frame& top = stack.back();
    if (top.next_joint == top.link->child_joints.size()) {
      stack.pop_back();
      if (!path_joints.empty()) path_joints.pop_back();
      continue;
    }
    const urdf::Joint& uj = *top.link->child_joints[top.next_joint++];
    const urdf::LinkConstSharedPtr child = model->getLink(uj.child_link_name);
    if (!child)
      fail(urdf_path, "joint " + in_quotes(uj.name) + " names a missing child link " +
                          in_quotes(uj.child_link_name));
    if (const auto seen = entered.find(child->name); seen != entered.end()) {
      const int depth = seen->second;
      const bool on_path = depth < static_cast<int>(stack.size()) &&
                           stack[static_cast<size_t>(depth)].link->name == child->name;
      if (on_path) {
        std::vector<std::string> cycle(path_joints.begin() + depth, path_joints.end());
        cycle.push_back(uj.name);
        fail(urdf_path, "joints form a cycle through link " + in_quotes(child->name) + ": " +
                            joint_list(cycle) + " (a URDF must be a tree)");
      }
      const int first = hand.links[static_cast<size_t>(find_link(hand, child->name))].parent_joint;
      fail(urdf_path, "link " + in_quotes(child->name) + " is the child of two joints, " +
                          in_quotes(hand.joints[static_cast<size_t>(first)].name) + " and " +
                          in_quotes(uj.name) + " (a URDF must be a tree)");
    }
    std::optional<std::string> master;
    hand.joints.push_back(convert_joint(uj, top.link_index, urdf_path, master));
    const int joint_index = static_cast<int>(hand.joints.size()) - 1;
    if (master) mimic_master[uj.name] = *master;
    hand.links.push_back(convert_link(*child, joint_index, *model, urdf_path, options, cache));
    const int child_index = static_cast<int>(hand.links.size()) - 1;
    hand.joints[static_cast<size_t>(joint_index)].child_link = child_index;
    entered[child->name] = static_cast<int>(stack.size());
    path_joints.push_back(uj.name);
    stack.push_back({child.get(), child_index});  // invalidates `top`
  }

  for (const auto& [joint_name, master_name] : mimic_master) {
    const int j = find_joint(hand, joint_name);
    const int m = find_joint(hand, master_name);
    if (m < 0)
      fail(urdf_path,
           "joint " + in_quotes(joint_name) + " mimics unknown joint " + in_quotes(master_name));
    if (!hand.joints[m].is_moving() || m == j)
      fail(urdf_path, "joint " + in_quotes(joint_name) + " mimics " + in_quotes(master_name) +
                          ", which is fixed or itself");
    hand.joints[j].mimic->master_joint = m;
  }
  for (const auto& joint : hand.joints)
    if (joint.mimic && hand.joints[joint.mimic->master_joint].mimic)
      fail(urdf_path, "joint " + in_quotes(joint.name) + " mimics " +
                          in_quotes(hand.joints[joint.mimic->master_joint].name) +
                          ", itself a mimic joint (chains are not supported)");

  if (std::none_of(hand.joints.begin(), hand.joints.end(),
                   [](const Joint& j) { return j.is_moving(); }))
    fail(urdf_path, "URDF has no moving joint (revolute, continuous or prismatic): not a hand");

  return hand;
}

}  // namespace cordgrasp::hand_load
