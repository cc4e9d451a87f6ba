// Hand description (YAML, docs/hand-description.md): reads it, imports the URDF it names and
// applies the description on top (GCP, couplings, preshape, actors, thumb links, overrides).
#include "cordgrasp/core/hand_description.h"

#include <yaml-cpp/yaml.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>
#include <vector>

#include "cordgrasp/core/assets.h"
#include "cordgrasp/core/kinematics.h"
#include "hand_load_common.h"
#include "substitute_inertial.h"
#include "urdf_import.h"

namespace fs = std::filesystem;

namespace cordgrasp {
namespace {

using hand_load::append_geometry_corners;
using hand_load::Box3;
using hand_load::fail;
using hand_load::import_urdf;
using hand_load::in_quotes;
using hand_load::warn_substituted_once;

/// A hand larger than this (any axis, preshape) is taken to be in millimetres [m].
constexpr double kMaxHandExtent_m = 2.0;
/// Tolerance on preshape values against joint limits [rad or m].
constexpr double kLimitTol = 1e-9;

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
                                                "soft_finger_radius_m", "palm_normal",
                                                "package_paths"};
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
  // A hand is centimetres across: an offset past a metre is a unit mistake or garbage.
  constexpr double kMaxGcpOffset_m = 1.0;
  const Eigen::Vector3d xyz = d.vec3(gcp["xyz"], "gcp.xyz");
  if (xyz.cwiseAbs().maxCoeff() > kMaxGcpOffset_m)
    d.error(gcp["xyz"], "gcp.xyz is farther than 1 m from the link (metres, not millimetres)");
  hand.gcp.X_LG = from_xyz_rpy(xyz, d.vec3(gcp["rpy"], "gcp.rpy"));
  for (const auto& kv : gcp) {
    const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : "?";
    if (key != "link" && key != "xyz" && key != "rpy")
      d.error(kv.first, "unknown key " + in_quotes("gcp." + key));
  }
}

void read_palm_normal(HandModel& hand, const Description& d) {
  const YAML::Node pn = d.root()["palm_normal"];
  if (!pn) return;
  d.require_map(pn, "palm_normal");
  for (const auto& kv : pn) {
    const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : "?";
    if (key != "link" && key != "axis")
      d.error(kv.first, "unknown key " + in_quotes("palm_normal." + key));
  }
  const std::string link = d.text(pn["link"], "palm_normal.link");
  PalmNormal normal;
  normal.link = find_link(hand, link);
  if (normal.link < 0)
    d.error(pn["link"], "palm_normal link " + in_quotes(link) + " not found in the URDF");
  if (!pn["axis"]) d.error(pn, "palm_normal needs 'axis: [x, y, z]'");
  const Eigen::Vector3d axis = d.vec3(pn["axis"], "palm_normal.axis");
  if (!(axis.norm() > 1e-9)) d.error(pn["axis"], "palm_normal.axis is the zero vector");
  normal.n_L = axis.normalized();
  hand.palm_normal = normal;
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

HandModel load_hand(const std::string& name_or_path, const HandLoadOptions& options) {
  const std::string desc_path = resolve_hand_path(name_or_path);
  const Description d(desc_path);
  if (d.root()["format"] && d.number(d.root()["format"], "format") != 1.0)
    d.error(d.root()["format"], "unsupported format (this cordgrasp reads format 1)");

  const YAML::Node name = d.root()["name"];
  const std::string hand_name = name ? d.text(name, "name") : fs::path(desc_path).stem().string();
  const YAML::Node urdf = d.root()["urdf"];
  if (!urdf) fail(desc_path, "missing 'urdf' (path of the hand's URDF, relative to this file)");
  const std::string urdf_text = d.text(urdf, "urdf");
  fs::path urdf_path(urdf_text);
  if (urdf_path.is_relative()) urdf_path = fs::path(desc_path).parent_path() / urdf_path;
  urdf_path = urdf_path.lexically_normal();
  if (!fs::is_regular_file(urdf_path))
    d.error(urdf, "URDF " + in_quotes(urdf_text) + " not found (looked for " +
                      in_quotes(urdf_path.string()) + ")");

  // package:// directories: the options', then the description's (relative to this file).
  HandLoadOptions with_description = options;
  if (const YAML::Node pkgs = d.root()["package_paths"]) {
    if (!pkgs.IsMap()) d.error(pkgs, "package_paths must be a mapping NAME: DIR");
    for (const auto& kv : pkgs) {
      const std::string package = d.text(kv.first, "package_paths");
      fs::path dir(d.text(kv.second, "package_paths." + package));
      if (dir.is_relative()) dir = fs::path(desc_path).parent_path() / dir;
      if (!fs::is_directory(dir))
        d.error(kv.second, "package_paths." + package + ": " + in_quotes(dir.string()) +
                               " is not a directory");
      with_description.package_paths.emplace(package, dir.lexically_normal().string());
    }
  }
  HandModel hand = import_urdf(urdf_path.string(), with_description);
  hand.name = hand_name;
  hand.description_path = desc_path;
  read_gcp(hand, d);
  read_couplings(hand, d);
  read_preshape(hand, d);
  read_actors(hand, d);
  read_thumb_links(hand, d);
  read_palm_normal(hand, d);
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
  std::vector<std::string> substituted;
  for (const Link& link : hand.links)
    if (link.inertial.substituted) substituted.push_back(link.name);
  if (!substituted.empty()) warn_substituted_once(hand.urdf_path, substituted);
  return hand;
}

}  // namespace cordgrasp
