// Hand loading: a YAML hand description plus the URDF it names (urdfdom), meshes via load_mesh.
#include "cordgrasp/core/hand_io.h"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>
#include <yaml-cpp/yaml.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <tuple>

#include "cordgrasp/core/assets.h"
#include "cordgrasp/core/error.h"
#include "cordgrasp/core/geometry_points.h"
#include "cordgrasp/core/kinematics.h"
#include "cordgrasp/core/mesh_io.h"

namespace fs = std::filesystem;

namespace cordgrasp {
namespace {

constexpr const char* kDefaultHand = "cordgrasp_sah";
/// A hand larger than this (any axis, preshape) is taken to be in millimetres [m].
constexpr double kMaxHandExtent_m = 2.0;
/// Substituted inertials: solid box of the link's geometry bounds at this density [kg/m³].
constexpr double kSubstituteDensity_kgm3 = 700.0;
/// Substituted inertials never go below this mass [kg].
constexpr double kMinSubstituteMass_kg = 0.001;
/// Side of the cube used for links without any geometry [m].
constexpr double kFrameCubeSide_m = 0.01;
/// Declared mass / bounding-box volume outside this range is a placeholder [kg/m³]: the box
/// over-estimates the volume, so a real link can only look lighter, never denser than steel.
constexpr double kMinPlausibleDensity_kgm3 = 20.0;
constexpr double kMaxPlausibleDensity_kgm3 = 10000.0;
/// Tolerance on preshape values against joint limits [rad or m].
constexpr double kLimitTol = 1e-9;

// ---------------------------------------------------------------------------------------------
// Errors

std::string in_quotes(const std::string& s) { return "'" + s + "'"; }

[[noreturn]] void fail(const std::string& file, const std::string& problem) {
  throw InputError("load_hand: " + in_quotes(file) + ": " + problem);
}

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
  if (!model) {
    std::string why = handler.first_error.empty() ? "malformed URDF" : handler.first_error;
    while (!why.empty() && (why.back() == '\n' || why.back() == ' ')) why.pop_back();
    fail(urdf_path, "URDF parse error: " + why);
  }
  return model;
}

Eigen::Isometry3d to_isometry(const urdf::Pose& pose) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  const auto& r = pose.rotation;
  X.linear() = Eigen::Quaterniond(r.w, r.x, r.y, r.z).normalized().toRotationMatrix();
  X.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  return X;
}

Eigen::Isometry3d from_xyz_rpy(const Eigen::Vector3d& xyz, const Eigen::Vector3d& rpy) {
  // URDF convention: fixed axes, R = Rz(yaw)·Ry(pitch)·Rx(roll).
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
                Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
                Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
                   .toRotationMatrix();
  X.translation() = xyz;
  return X;
}

// ---------------------------------------------------------------------------------------------
// Geometry

/// Meshes shared between links within one load (same file and scale).
using MeshCache =
    std::map<std::tuple<std::string, double, double, double>, std::shared_ptr<const Mesh>>;

std::string resolve_mesh_path(const std::string& urdf_path, const std::string& link,
                              const std::string& filename) {
  std::string name = filename;
  if (name.rfind("file://", 0) == 0) name = name.substr(7);
  if (name.rfind("package://", 0) == 0)
    fail(urdf_path, "link " + in_quotes(link) + " mesh " + in_quotes(filename) +
                        ": package:// URIs are not supported; use a path relative to the URDF");
  fs::path p(name);
  if (p.is_relative()) p = fs::path(urdf_path).parent_path() / p;
  p = p.lexically_normal();
  if (!fs::is_regular_file(p))
    fail(urdf_path, "link " + in_quotes(link) + ": mesh file " + in_quotes(filename) +
                        " not found (looked for " + in_quotes(p.string()) + ")");
  return p.string();
}

Geometry convert_geometry(const urdf::GeometrySharedPtr& g, const urdf::Pose& origin,
                          const std::string& urdf_path, const std::string& link, MeshCache& cache) {
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
      out.mesh_path = resolve_mesh_path(urdf_path, link, m.filename);
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

void append_geometry_corners(const Geometry& g, std::vector<Eigen::Vector3d>& out) {
  const auto pts = geometry_points(g);
  out.insert(out.end(), pts.begin(), pts.end());
}

struct Box3 {
  Eigen::Vector3d min = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d max = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());
  bool empty() const { return !(min.array() <= max.array()).all(); }
  void add(const Eigen::Vector3d& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
};

/// Bounds of the link's collision geometry (of its visuals when it has no collision geometry).
Box3 link_geometry_box(const Link& link) {
  std::vector<Eigen::Vector3d> pts;
  for (const auto& g : link.collisions) append_geometry_corners(g, pts);
  if (pts.empty())
    for (const auto& g : link.visuals) append_geometry_corners(g, pts);
  Box3 box;
  for (const auto& p : pts) box.add(p);
  return box;
}

// ---------------------------------------------------------------------------------------------
// Inertials

Eigen::Matrix3d solid_box_inertia(double mass, const Eigen::Vector3d& size) {
  const Eigen::Vector3d s2 = size.cwiseProduct(size);
  return Eigen::Vector3d(mass / 12.0 * (s2.y() + s2.z()), mass / 12.0 * (s2.x() + s2.z()),
                         mass / 12.0 * (s2.x() + s2.y()))
      .asDiagonal();
}

/// True when the inertia tensor is physically possible for a body of this mass (and, when the
/// geometry is known, one that fits inside a box of diagonal `diag_m`).
bool plausible_inertia(const Inertial& in, double diag_m) {
  const Eigen::Matrix3d& I = in.inertia_kgm2;
  if (!I.allFinite() || (I - I.transpose()).cwiseAbs().maxCoeff() > 1e-12 * I.norm() + 1e-15)
    return false;
  const Eigen::Vector3d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(I).eigenvalues();
  if (ev.minCoeff() <= 0.0) return false;
  const double tri_tol = 1e-9 * ev.sum();
  if (ev(0) + ev(1) < ev(2) - tri_tol) return false;  // triangle inequality
  // trace/2 = ∫|r|² dm <= m · (largest distance from the COM)² <= m · diag².
  if (diag_m > 0.0 && 0.5 * ev.sum() > in.mass_kg * diag_m * diag_m) return false;
  return true;
}

/// Replaces a missing or placeholder inertial; returns true when it did.
bool substitute_inertial_if_needed(Link& link, bool declared) {
  const Box3 box = link_geometry_box(link);
  const bool has_geometry = !box.empty();
  const Eigen::Vector3d size = has_geometry ? (box.max - box.min).eval() : Eigen::Vector3d::Zero();
  const double volume = size.prod();
  Inertial& in = link.inertial;
  bool mass_ok = declared && std::isfinite(in.mass_kg) && in.mass_kg > 0.0;
  if (mass_ok && has_geometry && volume > 0.0) {
    const double density = in.mass_kg / volume;
    mass_ok = density >= kMinPlausibleDensity_kgm3 && density <= kMaxPlausibleDensity_kgm3;
  }
  const bool inertia_ok = mass_ok && plausible_inertia(in, has_geometry ? size.norm() : 0.0);
  if (mass_ok && inertia_ok && in.com_m.allFinite()) return false;

  const Eigen::Vector3d box_size = has_geometry
                                       ? size.cwiseMax(Eigen::Vector3d::Constant(1e-3)).eval()
                                       : Eigen::Vector3d::Constant(kFrameCubeSide_m);
  const Eigen::Vector3d center =
      has_geometry ? (0.5 * (box.min + box.max)).eval() : Eigen::Vector3d::Zero();
  if (!mass_ok) {
    in.mass_kg = std::max(kMinSubstituteMass_kg, kSubstituteDensity_kgm3 * box_size.prod());
    in.com_m = center;
  } else if (has_geometry) {
    // Keep the declared mass; keep its COM when it lies inside the geometry bounds.
    const Eigen::Vector3d margin = 0.05 * box_size;
    const bool inside = in.com_m.allFinite() &&
                        (in.com_m.array() >= (box.min - margin).array()).all() &&
                        (in.com_m.array() <= (box.max + margin).array()).all();
    if (!inside) in.com_m = center;
  } else if (!in.com_m.allFinite()) {
    in.com_m = center;
  }
  in.inertia_kgm2 = solid_box_inertia(in.mass_kg, box_size);
  in.substituted = true;
  return true;
}

void warn_substituted_once(const std::string& urdf_path, const std::vector<std::string>& names) {
  static std::mutex mutex;
  static std::set<std::string> warned;
  std::lock_guard<std::mutex> lock(mutex);
  if (!warned.insert(urdf_path).second) return;
  std::ostringstream msg;
  msg << "cordgrasp: warning: " << in_quotes(urdf_path)
      << ": missing, placeholder or impossible inertials on " << names.size()
      << " link(s), replaced by solid boxes of their geometry bounds (" << kSubstituteDensity_kgm3
      << " kg/m^3 unless the declared mass is plausible): ";
  for (size_t i = 0; i < names.size(); ++i) msg << (i ? ", " : "") << in_quotes(names[i]);
  std::cerr << msg.str() << '\n';
}

// ---------------------------------------------------------------------------------------------
// URDF -> HandModel (kinematics, geometry, inertials)

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

/// Fills links and joints from the URDF; returns the links whose inertial was substituted.
std::vector<std::string> load_urdf_into(HandModel& hand, const std::string& urdf_path) {
  const urdf::ModelInterfaceSharedPtr model = parse_urdf(urdf_path);
  const urdf::LinkConstSharedPtr root = model->getRoot();
  if (!root) fail(urdf_path, "URDF has no root link");

  MeshCache cache;
  std::vector<std::string> substituted;
  std::map<std::string, std::string> mimic_master;  // joint -> master name

  auto add_link = [&](const urdf::Link& ul, int parent_joint) {
    Link link;
    link.name = ul.name;
    link.parent_joint = parent_joint;
    for (const auto& c : ul.collision_array)
      link.collisions.push_back(
          convert_geometry(c->geometry, c->origin, urdf_path, ul.name, cache));
    for (const auto& v : ul.visual_array) {
      Geometry g = convert_geometry(v->geometry, v->origin, urdf_path, ul.name, cache);
      g.rgba = material_rgba(*v, *model);
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
    if (substitute_inertial_if_needed(link, declared)) substituted.push_back(link.name);
    hand.links.push_back(std::move(link));
    return static_cast<int>(hand.links.size()) - 1;
  };

  // Depth-first from the root: a joint's parent link always precedes it.
  std::function<void(const urdf::Link&, int)> visit = [&](const urdf::Link& ul, int link_index) {
    for (const auto& uj : ul.child_joints) {
      Joint joint;
      joint.name = uj->name;
      joint.parent_link = link_index;
      joint.X_PJ = to_isometry(uj->parent_to_joint_origin_transform);
      const auto lim = uj->limits;
      switch (uj->type) {
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
          fail(urdf_path, "joint " + in_quotes(uj->name) +
                              ": unsupported type (only fixed, revolute, continuous, prismatic)");
      }
      if (joint.is_moving()) {
        joint.axis = Eigen::Vector3d(uj->axis.x, uj->axis.y, uj->axis.z);
        if (!joint.axis.allFinite() || joint.axis.norm() < 1e-12)
          fail(urdf_path, "joint " + in_quotes(uj->name) + " has a zero axis");
        joint.axis.normalize();
      }
      if (joint.type == JointType::kRevolute || joint.type == JointType::kPrismatic) {
        if (!lim) fail(urdf_path, "joint " + in_quotes(uj->name) + " has no <limit>");
        joint.lower = lim->lower;
        joint.upper = lim->upper;
        if (!std::isfinite(joint.lower) || !std::isfinite(joint.upper))
          fail(urdf_path, "joint " + in_quotes(uj->name) + " has non-finite limits");
        if (joint.lower > joint.upper) {
          std::ostringstream s;
          s << "joint " << in_quotes(uj->name) << " has inverted limits: lower " << joint.lower
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
      if (uj->mimic && joint.is_moving()) {
        Mimic m;
        m.multiplier = uj->mimic->multiplier;
        m.offset = uj->mimic->offset;
        joint.mimic = m;
        mimic_master[uj->name] = uj->mimic->joint_name;
      }
      const urdf::LinkConstSharedPtr child = model->getLink(uj->child_link_name);
      if (!child)
        fail(urdf_path, "joint " + in_quotes(uj->name) + " names a missing child link " +
                            in_quotes(uj->child_link_name));
      hand.joints.push_back(std::move(joint));
      const int joint_index = static_cast<int>(hand.joints.size()) - 1;
      const int child_index = add_link(*child, joint_index);
      hand.joints[joint_index].child_link = child_index;
      visit(*child, child_index);
    }
  };
  hand.root_link = add_link(*root, -1);
  visit(*root, hand.root_link);

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

  return substituted;
}

// ---------------------------------------------------------------------------------------------
// YAML description

class Description {
 public:
  explicit Description(std::string path) : path_(std::move(path)) {
    try {
      root_ = YAML::LoadFile(path_);
    } catch (const YAML::BadFile&) {
      fail(path_, "cannot read the hand description");
    } catch (const YAML::ParserException& e) {
      fail(path_, "YAML syntax error at line " + std::to_string(e.mark.line + 1) + ", column " +
                      std::to_string(e.mark.column + 1) + ": " + e.msg);
    }
    if (!root_.IsMap()) fail(path_, "hand description must be a YAML mapping (key: value)");
    static const std::set<std::string> kKeys = {"format",    "name",        "urdf",
                                                "gcp",       "preshape",    "actors",
                                                "couplings", "thumb_links", "palm_width_m",
                                                "soft_finger_radius_m"};
    for (const auto& kv : root_) {
      const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : "?";
      if (!kKeys.count(key)) error(kv.first, "unknown key " + in_quotes(key));
    }
  }

  const std::string& path() const { return path_; }
  const YAML::Node& root() const { return root_; }

  std::string line(const YAML::Node& n) const { return std::to_string(n.Mark().line + 1); }

  [[noreturn]] void error(const YAML::Node& at, const std::string& problem) const {
    if (at && at.Mark().line >= 0) fail(path_, problem + " (line " + line(at) + ")");
    fail(path_, problem);
  }

  double number(const YAML::Node& n, const std::string& what) const {
    if (!n || !n.IsScalar()) error(n, what + " must be a number");
    try {
      const double v = n.as<double>();
      if (!std::isfinite(v)) error(n, what + " must be finite");
      return v;
    } catch (const YAML::BadConversion&) {
      error(n, what + " must be a number, got " + in_quotes(n.Scalar()));
    }
  }

  std::string text(const YAML::Node& n, const std::string& what) const {
    if (!n || !n.IsScalar()) error(n, what + " must be a string");
    return n.Scalar();
  }

  Eigen::Vector3d vec3(const YAML::Node& n, const std::string& what) const {
    if (!n) return Eigen::Vector3d::Zero();
    if (!n.IsSequence() || n.size() != 3) error(n, what + " must be a list of 3 numbers");
    return Eigen::Vector3d(number(n[0], what), number(n[1], what), number(n[2], what));
  }

  void require_map(const YAML::Node& n, const std::string& what) const {
    if (!n.IsMap()) error(n, what + " must be a mapping");
  }
  void require_seq(const YAML::Node& n, const std::string& what) const {
    if (!n.IsSequence()) error(n, what + " must be a list");
  }

 private:
  std::string path_;
  YAML::Node root_;
};

int moving_joint(const HandModel& hand, const Description& d, const YAML::Node& key,
                 const std::string& what) {
  const std::string name = d.text(key, what);
  const int j = find_joint(hand, name);
  if (j < 0) d.error(key, what + " names unknown joint " + in_quotes(name));
  if (!hand.joints[j].is_moving()) d.error(key, what + " names fixed joint " + in_quotes(name));
  return j;
}

void read_gcp(HandModel& hand, const Description& d) {
  const YAML::Node gcp = d.root()["gcp"];
  if (!gcp) fail(d.path(), "missing 'gcp' (grasp centre point: link, xyz, rpy)");
  d.require_map(gcp, "gcp");
  const std::string link = d.text(gcp["link"], "gcp.link");
  hand.gcp.link = find_link(hand, link);
  if (hand.gcp.link < 0)
    d.error(gcp["link"], "GCP link " + in_quotes(link) + " not found in the URDF");
  hand.gcp.X_LG = from_xyz_rpy(d.vec3(gcp["xyz"], "gcp.xyz"), d.vec3(gcp["rpy"], "gcp.rpy"));
  for (const auto& kv : gcp) {
    const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : "?";
    if (key != "link" && key != "xyz" && key != "rpy")
      d.error(kv.first, "unknown key " + in_quotes("gcp." + key));
  }
}

void read_couplings(HandModel& hand, const Description& d) {
  const YAML::Node list = d.root()["couplings"];
  if (!list) return;
  d.require_seq(list, "couplings");
  for (const auto& c : list) {
    d.require_map(c, "a coupling");
    const int j = moving_joint(hand, d, c["joint"], "coupling joint");
    const int m = moving_joint(hand, d, c["master"], "coupling master");
    if (j == m)
      d.error(c["joint"], "coupling of joint " + in_quotes(hand.joints[j].name) + " to itself");
    if (hand.joints[j].mimic)
      d.error(c["joint"], "joint " + in_quotes(hand.joints[j].name) + " is already coupled");
    Mimic mimic;
    mimic.master_joint = m;
    mimic.multiplier = c["multiplier"] ? d.number(c["multiplier"], "coupling multiplier") : 1.0;
    mimic.offset = c["offset"] ? d.number(c["offset"], "coupling offset") : 0.0;
    hand.joints[j].mimic = mimic;
  }
  for (const auto& joint : hand.joints)
    if (joint.mimic && hand.joints[joint.mimic->master_joint].mimic)
      fail(d.path(), "joint " + in_quotes(joint.name) + " is coupled to " +
                         in_quotes(hand.joints[joint.mimic->master_joint].name) +
                         ", itself coupled (chains are not supported)");
}

void read_preshape(HandModel& hand, const Description& d) {
  Eigen::VectorXd q = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(hand.joints.size()));
  const YAML::Node pre = d.root()["preshape"];
  if (pre) {
    d.require_map(pre, "preshape");
    for (const auto& kv : pre) {
      const int j = moving_joint(hand, d, kv.first, "preshape");
      const Joint& joint = hand.joints[j];
      if (joint.mimic)
        d.error(kv.first, "preshape sets " + in_quotes(joint.name) +
                              ", a coupled joint following " +
                              in_quotes(hand.joints[joint.mimic->master_joint].name) +
                              "; set the master instead");
      const double v = d.number(kv.second, "preshape value of " + in_quotes(joint.name));
      if (v < joint.lower - kLimitTol || v > joint.upper + kLimitTol) {
        std::ostringstream s;
        s << "preshape value " << v << " of joint " << in_quotes(joint.name)
          << " is outside its limits [" << joint.lower << ", " << joint.upper << "]";
        d.error(kv.second, s.str());
      }
      q[j] = v;
    }
  }
  hand.preshape = clamp_to_limits(hand, apply_couplings(hand, clamp_to_limits(hand, q)));
}

void read_actors(HandModel& hand, const Description& d) {
  const YAML::Node list = d.root()["actors"];
  if (!list) fail(d.path(), "missing 'actors' (one entry per closing finger)");
  d.require_seq(list, "actors");
  std::set<int> used;
  std::set<std::string> names;
  for (const auto& a : list) {
    d.require_map(a, "an actor");
    Actor actor;
    actor.name = d.text(a["name"], "actor name");
    if (!names.insert(actor.name).second)
      d.error(a["name"], "duplicate actor " + in_quotes(actor.name));
    const YAML::Node joints = a["joints"];
    if (!joints || !joints.IsMap() || joints.size() == 0)
      d.error(a, "actor " + in_quotes(actor.name) + " needs 'joints: {joint: speed, ...}'");
    for (const auto& kv : joints) {
      const int j = moving_joint(hand, d, kv.first, "actor " + in_quotes(actor.name));
      if (hand.joints[j].mimic)
        d.error(kv.first, "actor " + in_quotes(actor.name) + " lists " +
                              in_quotes(hand.joints[j].name) +
                              ", a coupled joint; list its master only");
      if (!used.insert(j).second)
        d.error(kv.first, "joint " + in_quotes(hand.joints[j].name) + " is in two actors");
      const double speed = d.number(kv.second, "speed of " + in_quotes(hand.joints[j].name));
      if (speed == 0.0) d.error(kv.second, "speed of " + in_quotes(hand.joints[j].name) + " is 0");
      actor.joints.push_back({j, speed});
    }
    hand.actors.push_back(std::move(actor));
  }
  if (hand.actors.empty()) fail(d.path(), "'actors' is empty");
}

void read_thumb_links(HandModel& hand, const Description& d) {
  const YAML::Node list = d.root()["thumb_links"];
  if (!list) return;
  d.require_seq(list, "thumb_links");
  for (const auto& n : list) {
    const std::string name = d.text(n, "thumb link");
    const int l = find_link(hand, name);
    if (l < 0) d.error(n, "thumb link " + in_quotes(name) + " not found in the URDF");
    hand.thumb_links.push_back(l);
  }
}

/// Rejects hands whose size in preshape says the URDF is in millimetres.
void check_size(const HandModel& hand) {
  const auto X_WL = link_poses(hand, hand.preshape);
  Box3 box;
  std::vector<Eigen::Vector3d> pts;
  for (size_t l = 0; l < hand.links.size(); ++l) {
    box.add(X_WL[l].translation());
    pts.clear();
    for (const auto& g : hand.links[l].collisions) append_geometry_corners(g, pts);
    for (const auto& g : hand.links[l].visuals) append_geometry_corners(g, pts);
    for (const auto& p : pts) box.add(X_WL[l] * p);
  }
  const double extent = (box.max - box.min).maxCoeff();
  if (extent > kMaxHandExtent_m) {
    std::ostringstream s;
    s << "hand is " << extent << " m across in preshape (> " << kMaxHandExtent_m
      << " m): the URDF looks like it is in millimetres; URDF lengths must be meters";
    fail(hand.urdf_path, s.str());
  }
}

}  // namespace

std::string shipped_hands_dir() { return (fs::path(assets_dir()) / "hands").string(); }

const char* default_hand_name() { return kDefaultHand; }

std::string resolve_hand_path(const std::string& name_or_path) {
  if (name_or_path.empty()) throw InputError("--hand: empty hand name");
  const fs::path given(name_or_path);
  if (fs::is_regular_file(given)) {
    const std::string ext = given.extension().string();
    if (ext == ".urdf" || ext == ".URDF" || ext == ".xml")
      throw InputError("--hand " + in_quotes(name_or_path) +
                       ": this is a URDF; pass the hand description (YAML) that names it");
    return given.string();
  }
  if (fs::is_directory(given)) {  // a hand folder: <dir>/<dir name>.yaml
    const fs::path inside = given / (given.lexically_normal().filename().string() + ".yaml");
    if (fs::is_regular_file(inside)) return inside.string();
  }
  const fs::path dir = shipped_hands_dir();
  for (const fs::path& p :
       {dir / (name_or_path + ".yaml"), dir / name_or_path / (name_or_path + ".yaml")})
    if (fs::is_regular_file(p)) return p.lexically_normal().string();
  std::vector<std::string> names;
  if (fs::is_directory(dir))
    for (const auto& e : fs::directory_iterator(dir)) {
      if (e.path().extension() == ".yaml") names.push_back(e.path().stem().string());
      if (e.is_directory() &&
          fs::is_regular_file(e.path() / (e.path().filename().string() + ".yaml")))
        names.push_back(e.path().filename().string());
    }
  std::sort(names.begin(), names.end());
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  throw InputError("--hand " + in_quotes(name_or_path) +
                   ": no such description file and no shipped hand of that name (shipped in " +
                   in_quotes(dir.string()) + ": " + (list.empty() ? "none" : list) + ")");
}

HandModel load_hand(const std::string& name_or_path) {
  const std::string desc_path = resolve_hand_path(name_or_path);
  const Description d(desc_path);
  if (d.root()["format"] && d.number(d.root()["format"], "format") != 1.0)
    d.error(d.root()["format"], "unsupported format (this cordgrasp reads format 1)");

  HandModel hand;
  hand.description_path = desc_path;
  hand.name =
      d.root()["name"] ? d.text(d.root()["name"], "name") : fs::path(desc_path).stem().string();
  const YAML::Node urdf = d.root()["urdf"];
  if (!urdf) fail(desc_path, "missing 'urdf' (path of the hand's URDF, relative to this file)");
  const std::string urdf_text = d.text(urdf, "urdf");
  fs::path urdf_path(urdf_text);
  if (urdf_path.is_relative()) urdf_path = fs::path(desc_path).parent_path() / urdf_path;
  urdf_path = urdf_path.lexically_normal();
  if (!fs::is_regular_file(urdf_path))
    d.error(urdf, "URDF " + in_quotes(urdf_text) + " not found (looked for " +
                      in_quotes(urdf_path.string()) + ")");
  hand.urdf_path = urdf_path.string();

  const std::vector<std::string> substituted = load_urdf_into(hand, hand.urdf_path);
  read_gcp(hand, d);
  read_couplings(hand, d);
  read_preshape(hand, d);
  read_actors(hand, d);
  read_thumb_links(hand, d);
  if (const YAML::Node w = d.root()["palm_width_m"]) {
    const double v = d.number(w, "palm_width_m");
    if (!(v > 0.0 && v < 1.0)) d.error(w, "palm_width_m must be in (0, 1) m");
    hand.palm_width_m = v;
  }
  if (const YAML::Node r = d.root()["soft_finger_radius_m"]) {
    const double v = d.number(r, "soft_finger_radius_m");
    if (!(v >= 0.0 && v < 0.05)) d.error(r, "soft_finger_radius_m must be in [0, 0.05) m");
    hand.soft_finger_radius_m = v;
  }
  check_size(hand);
  if (!substituted.empty()) warn_substituted_once(hand.urdf_path, substituted);
  return hand;
}

}  // namespace cordgrasp
