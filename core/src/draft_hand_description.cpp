#include "cordgrasp/core/draft_hand_description.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iterator>
#include <map>
#include <sstream>

#include "cordgrasp/core/error.h"
#include "cordgrasp/core/geometry_points.h"
#include "cordgrasp/core/hand_conventions.h"
#include "cordgrasp/core/kinematics.h"
#include "urdf_import.h"

namespace fs = std::filesystem;

namespace cordgrasp {
namespace {

/// A joint closes its finger when the tip moves at least this much along the closing direction
/// (cosine of the angle between the tip velocity and that direction).
constexpr double kMinClosingCosine = 0.5;
/// Finite-difference step for tip velocities [rad or m].
constexpr double kStep = 1e-3;
/// Revolute limits count as asymmetric (a flexion joint) when the larger side exceeds the
/// smaller by this fraction of the range.
constexpr double kAsymmetry = 0.2;

struct DraftFinger {
  int root_joint = -1;
  std::vector<int> links;   ///< subtree of the root joint's child
  std::vector<int> joints;  ///< moving, not mimic, in the subtree
  int tip_link = -1;
  Eigen::Vector3d p_tip_L = Eigen::Vector3d::Zero();
  bool driven_elsewhere = false;  ///< every moving joint mimics a joint of another finger
};

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string num(double v) {
  std::ostringstream s;
  s << std::setprecision(6) << (std::abs(v) < 1e-12 ? 0.0 : v);
  return s.str();
}

std::string vec(const Eigen::Vector3d& v) {
  return "[" + num(v.x()) + ", " + num(v.y()) + ", " + num(v.z()) + "]";
}

Eigen::Vector3d tip_W(const HandModel& hand, const DraftFinger& f, const Eigen::VectorXd& q) {
  return link_poses(hand, apply_couplings(hand, q))[f.tip_link] * f.p_tip_L;
}

/// Tip velocity of finger f for joint j at q (central difference inside the limits).
Eigen::Vector3d tip_velocity(const HandModel& hand, const DraftFinger& f, const Eigen::VectorXd& q,
                             int j) {
  const Joint& joint = hand.joints[j];
  Eigen::VectorXd a = q, b = q;
  a[j] = std::max(joint.lower, q[j] - kStep);
  b[j] = std::min(joint.upper, q[j] + kStep);
  if (!(b[j] > a[j])) return Eigen::Vector3d::Zero();
  return (tip_W(hand, f, b) - tip_W(hand, f, a)) / (b[j] - a[j]);
}

std::vector<DraftFinger> find_fingers(const HandModel& hand) {
  const size_t nl = hand.links.size();
  std::vector<std::vector<int>> child_joints(nl);
  for (size_t j = 0; j < hand.joints.size(); ++j)
    child_joints[hand.joints[j].parent_link].push_back(static_cast<int>(j));
  // moving leaves below each link: links whose parent joint moves and with no moving joint
  // further down; joints are in topological order, so walk them backwards.
  std::vector<int> leaves(nl, 0);
  std::vector<bool> moving_below(nl, false);
  for (int j = static_cast<int>(hand.joints.size()) - 1; j >= 0; --j) {
    const Joint& joint = hand.joints[j];
    const int c = joint.child_link;
    if (joint.is_moving() && !moving_below[c]) leaves[c] = std::max(leaves[c], 1);
    leaves[joint.parent_link] += leaves[c];
    if (joint.is_moving() || moving_below[c]) moving_below[joint.parent_link] = true;
  }
  std::vector<int> finger_of(nl, -1);
  std::vector<DraftFinger> fingers;
  for (size_t j = 0; j < hand.joints.size(); ++j) {
    const Joint& joint = hand.joints[j];
    const int p = joint.parent_link, c = joint.child_link;
    if (finger_of[p] >= 0) {
      finger_of[c] = finger_of[p];
    } else if (joint.is_moving() && leaves[c] == 1) {
      finger_of[c] = static_cast<int>(fingers.size());
      fingers.push_back({});
      fingers.back().root_joint = static_cast<int>(j);
    }
    if (finger_of[c] >= 0) {
      DraftFinger& f = fingers[finger_of[c]];
      f.links.push_back(c);
      if (joint.is_moving() && joint.type != JointType::kContinuous) f.joints.push_back(
          static_cast<int>(j));
    }
  }
  // Fingertip: the finger's collision point farthest from its root joint, at q = 0.
  const Eigen::VectorXd q0 =
      apply_couplings(hand, clamp_to_limits(hand, Eigen::VectorXd::Zero(hand.joints.size())));
  const auto X = link_poses(hand, q0);
  std::vector<DraftFinger> out;
  for (DraftFinger& f : fingers) {
    const Eigen::Vector3d root = X[hand.joints[f.root_joint].child_link].translation();
    double best = -1.0;
    std::vector<Eigen::Vector3d> pts;
    for (int l : f.links) {
      pts.clear();
      append_collision_points(hand.links[l], pts);
      for (const auto& p : pts) {
        const double d = (X[l] * p - root).norm();
        if (d > best) {
          best = d;
          f.tip_link = l;
          f.p_tip_L = p;
        }
      }
    }
    if (f.tip_link < 0) continue;  // no geometry: not a finger
    bool all_mimic = true;
    std::vector<int> own;
    for (int j : f.joints) {
      if (!hand.joints[j].mimic) {
        own.push_back(j);
        all_mimic = false;
      }
    }
    f.driven_elsewhere = all_mimic && !f.joints.empty();
    f.joints = own;
    out.push_back(f);
  }
  return out;
}

/// Lowest common ancestor link of the fingers' roots (the palm).
int palm_link(const HandModel& hand, const std::vector<DraftFinger>& fingers) {
  auto path = [&](int link) {
    std::vector<int> up;
    for (int l = link; l >= 0;) {
      up.push_back(l);
      const int pj = hand.links[l].parent_joint;
      l = pj >= 0 ? hand.joints[pj].parent_link : -1;
    }
    std::reverse(up.begin(), up.end());
    return up;
  };
  std::vector<int> common = path(hand.joints[fingers[0].root_joint].parent_link);
  for (const DraftFinger& f : fingers) {
    const std::vector<int> p = path(hand.joints[f.root_joint].parent_link);
    size_t k = 0;
    while (k < common.size() && k < p.size() && common[k] == p[k]) ++k;
    common.resize(k);
  }
  return common.empty() ? hand.root_link : common.back();
}

std::string finger_name(const HandModel& hand, const DraftFinger& f) {
  return hand.links[hand.joints[f.root_joint].child_link].name;
}

}  // namespace

HandDraft draft_hand_description(const std::string& urdf_path, const std::string& out_path,
                                 const HandLoadOptions& options) {
  HandDraft draft;
  HandModel& hand = draft.hand;
  hand = hand_load::import_urdf(urdf_path, options);
  hand.name = fs::path(out_path).stem().string();
  hand.description_path = out_path;
  auto guess = [&](const std::string& what, const std::string& value, double confidence,
                   const std::string& why) {
    draft.guesses.push_back({what, value, std::clamp(confidence, 0.0, 1.0), why});
  };

  std::vector<DraftFinger> fingers = find_fingers(hand);
  if (fingers.empty())
    throw InputError("hand init: '" + urdf_path + "': no finger found (no chain of moving "
                     "joints with collision geometry below a common palm link)");
  const Eigen::VectorXd q0 = clamp_to_limits(hand, Eigen::VectorXd::Zero(hand.joints.size()));
  hand.preshape = clamp_to_limits(hand, apply_couplings(hand, q0));
  const auto X0 = link_poses(hand, hand.preshape);
  const int palm = palm_link(hand, fingers);
  {
    std::ostringstream names;
    for (size_t i = 0; i < fingers.size(); ++i)
      names << (i ? ", " : "") << finger_name(hand, fingers[i]);
    guess("fingers", std::to_string(fingers.size()) + " (" + names.str() + ")", 0.9,
          "chains below '" + hand.links[palm].name + "' ending in one moving leaf");
  }

  // Thumb: the finger whose root and tip are farthest from the others'.
  const size_t nf = fingers.size();
  std::vector<Eigen::Vector3d> roots(nf), tips(nf), centres(nf);
  for (size_t i = 0; i < nf; ++i) {
    roots[i] = X0[hand.joints[fingers[i].root_joint].child_link].translation();
    tips[i] = X0[fingers[i].tip_link] * fingers[i].p_tip_L;
    // Centroid of the finger's collision points: on a straight finger's centre line, unlike the
    // tip (a corner of its box).
    centres[i] = Eigen::Vector3d::Zero();
    int n = 0;
    std::vector<Eigen::Vector3d> pts;
    for (int l : fingers[i].links) {
      pts.clear();
      append_collision_points(hand.links[l], pts);
      for (const auto& p : pts) {
        centres[i] += X0[l] * p;
        ++n;
      }
    }
    centres[i] /= std::max(n, 1);
  }
  int thumb = 0;
  double confidence_thumb = 0.0;
  if (nf > 1) {
    std::vector<double> score(nf, 0.0);
    for (size_t i = 0; i < nf; ++i) {
      Eigen::Vector3d r = Eigen::Vector3d::Zero(), t = Eigen::Vector3d::Zero();
      for (size_t k = 0; k < nf; ++k)
        if (k != i) {
          r += roots[k] / double(nf - 1);
          t += tips[k] / double(nf - 1);
        }
      score[i] = (roots[i] - r).norm() + (tips[i] - t).norm();
    }
    // Fingers driven by another finger's joints (a mimic gripper jaw) are never the thumb's
    // actor; ties keep the first finger.
    for (size_t i = 0; i < nf; ++i)
      if (score[i] > score[thumb] * (1 + 1e-6) && !fingers[i].driven_elsewhere) thumb = int(i);
    double second = 0.0;
    for (size_t i = 0; i < nf; ++i)
      if (int(i) != thumb) second = std::max(second, score[i]);
    confidence_thumb = score[thumb] > 0 ? 1.0 - second / score[thumb] : 0.0;
    if (nf == 2) confidence_thumb = 0.0;
  }
  guess("thumb", finger_name(hand, fingers[thumb]), confidence_thumb,
        nf == 2 ? "two fingers: either opposes the other"
                : "root and tip farthest from the other fingers'");

  // Palm normal: the non-thumb fingers' flexion direction (joints with asymmetric limits,
  // towards the larger side), without its component along the fingers' extension.
  Eigen::Vector3d extension = Eigen::Vector3d::Zero(), flexion = Eigen::Vector3d::Zero();
  Eigen::Vector3d others_tips = Eigen::Vector3d::Zero();
  int n_others = 0;
  // Flexion of finger i (one-sided revolute joints towards their larger side), each joint's tip
  // motion without the finger's own extension.
  auto finger_flexion = [&](size_t i) {
    Eigen::Vector3d flexion = Eigen::Vector3d::Zero();
    for (int j : fingers[i].joints) {
      const Joint& joint = hand.joints[j];
      if (joint.type != JointType::kRevolute) continue;
      const double up = joint.upper - q0[j], down = q0[j] - joint.lower;
      if (std::abs(up - down) < kAsymmetry * (joint.upper - joint.lower)) continue;
      Eigen::Vector3d v = tip_velocity(hand, fingers[i], q0, j);
      const Eigen::Vector3d e = (centres[i] - roots[i]).normalized();
      v -= v.dot(e) * e;  // without the finger's own extension
      if (v.norm() > 1e-9) flexion += (up > down ? 1.0 : -1.0) * v.normalized();
    }
    return flexion;
  };
  for (size_t i = 0; i < nf; ++i) {
    if (int(i) == thumb) continue;
    extension += (centres[i] - roots[i]).normalized();
    others_tips += tips[i];
    ++n_others;
    flexion += finger_flexion(i);
  }
  // A thumb that flexes like the fingers (a Barrett-like hand) counts too; one that flexes
  // towards them (a human-like thumb) does not.
  if (nf > 2) {
    const Eigen::Vector3d f_thumb = finger_flexion(static_cast<size_t>(thumb));
    if (f_thumb.norm() > 1e-9 && flexion.norm() > 1e-9 &&
        f_thumb.normalized().dot(flexion.normalized()) > kMinClosingCosine)
      flexion += f_thumb;
  }
  if (n_others == 0) {  // one finger: it is the thumb and the rest of the hand
    n_others = 1;
    others_tips = tips[thumb];
    extension = (tips[thumb] - roots[thumb]).normalized();
  }
  others_tips /= n_others;
  extension.normalize();
  Eigen::Vector3d normal_W = flexion - flexion.dot(extension) * extension;
  double confidence_normal = flexion.norm() > 1e-9 ? normal_W.norm() / flexion.norm() : 0.0;
  std::string normal_why = "flexion of the fingers with one-sided joint limits";
  if (normal_W.norm() < 1e-6) {
    // Parallel jaws: the palm faces where the fingers point: from the palm's centroid to the
    // fingers' geometry centroid, without the jaw-to-jaw component.
    Eigen::Vector3d palm_c = Eigen::Vector3d::Zero(), fingers_c = Eigen::Vector3d::Zero();
    std::vector<bool> in_finger(hand.links.size(), false);
    for (const DraftFinger& f : fingers)
      for (int l : f.links) in_finger[l] = true;
    int n_palm = 0, n_fing = 0;
    std::vector<Eigen::Vector3d> pts;
    for (size_t l = 0; l < hand.links.size(); ++l) {
      pts.clear();
      append_collision_points(hand.links[l], pts);
      for (const auto& p : pts) {
        if (in_finger[l]) {
          fingers_c += X0[l] * p;
          ++n_fing;
        } else {
          palm_c += X0[l] * p;
          ++n_palm;
        }
      }
    }
    normal_W = extension;
    if (n_palm > 0 && n_fing > 0) {
      normal_W = fingers_c / n_fing - palm_c / n_palm;
      if (nf == 2) {
        const Eigen::Vector3d jaw = (centres[1] - centres[0]).normalized();
        normal_W -= normal_W.dot(jaw) * jaw;
      }
    }
    confidence_normal = 0.7;
    normal_why = "no flexion joints: along the fingers";
  }
  normal_W.normalize();
  const Eigen::Matrix3d R_WP = X0[palm].linear();
  hand.palm_normal = PalmNormal{palm, R_WP.transpose() * normal_W};
  guess("palm normal", "'" + hand.links[palm].name + "' " + vec(hand.palm_normal->n_L),
        confidence_normal, normal_why);

  // Closing joints and their signs.
  const Eigen::Vector3d thumb_tip = tips[thumb];
  for (size_t i = 0; i < nf; ++i) {
    const DraftFinger& f = fingers[i];
    if (f.driven_elsewhere || f.joints.empty()) continue;
    const bool is_thumb = int(i) == thumb;
    Actor actor;
    actor.name = is_thumb ? "thumb" : finger_name(hand, f);
    double worst = 1.0;
    std::ostringstream listed;
    for (int j : f.joints) {
      const Joint& joint = hand.joints[j];
      const Eigen::Vector3d v = tip_velocity(hand, f, q0, j);
      if (v.norm() < 1e-9) continue;
      Eigen::Vector3d towards = normal_W;
      if (joint.type == JointType::kPrismatic || is_thumb) {
        const Eigen::Vector3d target = is_thumb ? others_tips : thumb_tip;
        towards = target - tips[i];
        if (joint.type == JointType::kPrismatic && nf == 2) towards = tips[1 - i] - tips[i];
        towards -= towards.dot(normal_W) * normal_W;
        if (towards.norm() < 1e-9) continue;
        towards.normalize();
      }
      double c = v.normalized().dot(towards);
      if (is_thumb && joint.type != JointType::kPrismatic) {
        // A revolute thumb closes towards the others, or towards them and the palm's front.
        const double c2 = v.normalized().dot((towards + normal_W).normalized());
        if (std::abs(c2) > std::abs(c)) c = c2;
      }
      if (std::abs(c) < kMinClosingCosine) continue;
      const double speed =
          (c > 0 ? 1.0 : -1.0) * (joint.type == JointType::kPrismatic ? 0.1 : 1.0);
      actor.joints.push_back({j, speed});
      worst = std::min(worst, std::abs(c));
      listed << (actor.joints.size() > 1 ? ", " : "") << joint.name << (c > 0 ? " +" : " -");
    }
    // A thumb with more closing joints than two: its root joint turns it into opposition.
    if (is_thumb && actor.joints.size() > 2 && actor.joints.front().joint == f.joints.front()) {
      actor.joints.erase(actor.joints.begin());
      listed.str("");
      for (size_t k = 0; k < actor.joints.size(); ++k)
        listed << (k ? ", " : "") << hand.joints[actor.joints[k].joint].name
               << (actor.joints[k].direction_speed > 0 ? " +" : " -");
      listed << " (root joint " << hand.joints[f.joints.front()].name << " left to the preshape)";
    }
    if (actor.joints.empty()) continue;
    guess("actor " + actor.name, listed.str(), worst,
          is_thumb ? "tip moves towards the other fingertips"
                   : "tip moves along the palm normal");
    hand.actors.push_back(std::move(actor));
  }
  if (hand.actors.empty())
    throw InputError("hand init: '" + urdf_path + "': no joint closes any finger");
  for (int l : fingers[thumb].links) hand.thumb_links.push_back(l);
  // Prismatic closing joints start open: at the limit their closing motion leaves.
  Eigen::VectorXd q_open = q0;
  for (const Actor& a : hand.actors)
    for (const auto& e : a.joints) {
      const Joint& joint = hand.joints[e.joint];
      if (joint.type == JointType::kPrismatic)
        q_open[e.joint] = e.direction_speed > 0 ? joint.lower : joint.upper;
    }
  if (q_open != q0) {
    hand.preshape = clamp_to_limits(hand, apply_couplings(hand, q_open));
    const auto X1 = link_poses(hand, hand.preshape);
    for (size_t i = 0; i < nf; ++i) tips[i] = X1[fingers[i].tip_link] * fingers[i].p_tip_L;
    others_tips = Eigen::Vector3d::Zero();
    for (size_t i = 0; i < nf; ++i)
      if (int(i) != thumb) others_tips += tips[i] / double(std::max(1, int(nf) - 1));
    if (nf == 1) others_tips = tips[thumb];
  }
  const Eigen::Vector3d thumb_tip_open = tips[thumb];

  // GCP: between the thumb tip and the other fingertips, +z along the palm normal, at the
  // height (along it) that passes the convention checks best.
  Eigen::Vector3d palm_c = Eigen::Vector3d::Zero();
  double palm_top = -1e9;
  {
    std::vector<bool> in_finger(hand.links.size(), false);
    for (const DraftFinger& f : fingers)
      for (int l : f.links) in_finger[l] = true;
    std::vector<Eigen::Vector3d> pts, all;
    for (size_t l = 0; l < hand.links.size(); ++l) {
      if (in_finger[l]) continue;
      pts.clear();
      append_collision_points(hand.links[l], pts);
      for (const auto& p : pts) all.push_back(X0[l] * p);
    }
    for (const auto& p : all) palm_c += p / double(all.size());
    for (const auto& p : all) palm_top = std::max(palm_top, (p - palm_c).dot(normal_W));
    if (all.empty()) palm_top = 0.0;
  }
  // Laterally: between the tip links' centroids (a tip point is a corner of its finger).
  std::vector<Eigen::Vector3d> tip_centres(nf);
  {
    const auto X1 = link_poses(hand, hand.preshape);
    for (size_t i = 0; i < nf; ++i) {
      std::vector<Eigen::Vector3d> pts;
      append_collision_points(hand.links[fingers[i].tip_link], pts);
      Eigen::Vector3d c = Eigen::Vector3d::Zero();
      for (const auto& p : pts) c += X1[fingers[i].tip_link] * p / double(pts.size());
      tip_centres[i] = c;
    }
  }
  Eigen::Vector3d others_centre = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < nf; ++i)
    if (int(i) != thumb) others_centre += tip_centres[i] / double(std::max(1, int(nf) - 1));
  Eigen::Vector3d mid = 0.5 * (tip_centres[thumb] + others_centre);
  mid += (0.5 * (thumb_tip_open + others_tips) - mid).dot(normal_W) * normal_W;
  if (nf == 1) mid = tips[thumb];
  Eigen::Vector3d x_W = tip_centres[thumb] - mid;
  x_W -= x_W.dot(normal_W) * normal_W;
  if (x_W.norm() < 1e-9) x_W = normal_W.unitOrthogonal();
  x_W.normalize();
  Eigen::Matrix3d R_WG;
  R_WG.col(0) = x_W;
  R_WG.col(2) = normal_W;
  R_WG.col(1) = normal_W.cross(x_W);
  const double mid_h = (mid - palm_c).dot(normal_W);
  double best_h = mid_h;
  size_t best_problems = static_cast<size_t>(-1);
  double tips_top = mid_h;
  for (const auto& t : tips) tips_top = std::max(tips_top, (t - palm_c).dot(normal_W));
  const double lo = 0.005, hi = tips_top + 0.03;  // from just in front of the palm centroid
  // Preferred height: jaws meet the object 2 cm below their tips (as the shipped grippers);
  // fingered hands 1.5 cm behind the front of the palm's bounds (which hold knuckles and thumb
  // base), or at the fingertips' midpoint when that is lower.
  const double target_h = nf == 2 ? tips_top - 0.02 : std::min(mid_h, palm_top - 0.015);
  hand.gcp.link = palm;
  for (int k = 0; k <= 20; ++k) {
    const double h = lo + (hi - lo) * k / 20.0;
    Eigen::Isometry3d X_WG = Eigen::Isometry3d::Identity();
    X_WG.linear() = R_WG;
    X_WG.translation() = mid + (h - mid_h) * normal_W;
    hand.gcp.X_LG = X0[palm].inverse() * X_WG;
    const size_t p = check_hand_conventions(hand).size();
    // Fewest problems; among equals, nearest the preferred height.
    if (p < best_problems ||
        (p == best_problems && std::abs(h - target_h) < std::abs(best_h - target_h))) {
      best_problems = p;
      best_h = h;
    }
  }
  {
    Eigen::Isometry3d X_WG = Eigen::Isometry3d::Identity();
    X_WG.linear() = R_WG;
    X_WG.translation() = mid + (best_h - mid_h) * normal_W;
    hand.gcp.X_LG = X0[palm].inverse() * X_WG;
  }
  guess("gcp", "'" + hand.links[palm].name + "' xyz " + vec(hand.gcp.X_LG.translation()),
        best_problems == 0 ? 0.7 : 0.3,
        "between thumb tip and fingertips, " + num((best_h - palm_top) * 1000) +
            " mm from the front of the palm's bounds along the palm normal");
  {
    int nonzero = 0;
    for (Eigen::Index j = 0; j < q_open.size(); ++j) nonzero += q_open[j] != 0.0;
    guess("preshape", nonzero ? std::to_string(nonzero) + " joints not at 0" : "all joints 0",
          0.5, "the URDF's zero configuration clamped to the limits; prismatic jaws open");
  }
  int mimics = 0;
  for (const Joint& j : hand.joints) mimics += j.mimic.has_value();
  guess("couplings", std::to_string(mimics) + " from URDF <mimic>, none added", mimics ? 0.9 : 0.5,
        "the URDF's own <mimic> tags; tendon couplings it omits are not guessed");
  if (nf == 2) {
    hand.soft_finger_radius_m = 0.005;
    guess("soft_finger_radius_m", "0.005", 0.6,
          "two fingers: point contacts are never force closure, 5 mm pads");
  }
  draft.problems = check_hand_conventions(hand);

  // YAML.
  std::ostringstream y;
  fs::path urdf_rel = fs::absolute(urdf_path).lexically_normal();
  const fs::path out_dir = fs::absolute(out_path).parent_path();
  fs::path rel = urdf_rel.lexically_relative(out_dir);
  // Relative only when the two share more than the root directory.
  if (!rel.empty() && urdf_rel.begin() != urdf_rel.end() &&
      std::next(urdf_rel.begin()) != urdf_rel.end() &&
      std::next(out_dir.begin()) != out_dir.end() &&
      *std::next(urdf_rel.begin()) != *std::next(out_dir.begin()))
    rel.clear();
  y << "# cordgrasp hand description, format 1 (drafted by `cordgrasp hand init`; check it, see\n"
    << "# docs/hand-description.md, \"Drafting a description\").\n";
  y << "format: 1\nname: " << quoted(hand.name) << "\n";
  y << "urdf: " << quoted(rel.empty() ? urdf_rel.string() : rel.string()) << "\n";
  if (!options.package_paths.empty()) {  // so that every command finds them again
    y << "package_paths:\n";
    for (const auto& [package, dir] : options.package_paths)
      y << "  " << quoted(package) << ": " << quoted(fs::absolute(dir).lexically_normal().string())
        << "\n";
  }
  const Eigen::Vector3d rpy_zyx = hand.gcp.X_LG.linear().eulerAngles(2, 1, 0);
  y << "gcp:\n  link: " << quoted(hand.links[palm].name) << "\n  xyz: "
    << vec(hand.gcp.X_LG.translation()) << "\n  rpy: "
    << vec(Eigen::Vector3d(rpy_zyx[2], rpy_zyx[1], rpy_zyx[0])) << "\n";
  y << "palm_normal: {link: " << quoted(hand.links[palm].name)
    << ", axis: " << vec(hand.palm_normal->n_L) << "}\n";
  bool any = false;
  for (Eigen::Index j = 0; j < q_open.size(); ++j)
    if (q_open[j] != 0.0 && hand.joints[j].is_moving() && !hand.joints[j].mimic) {
      if (!any) y << "preshape:\n";
      any = true;
      y << "  " << quoted(hand.joints[j].name) << ": " << num(q_open[j]) << "\n";
    }
  y << "actors:\n";
  for (const Actor& a : hand.actors) {
    y << "  - name: " << quoted(a.name) << "\n    joints: {";
    for (size_t k = 0; k < a.joints.size(); ++k)
      y << (k ? ", " : "") << quoted(hand.joints[a.joints[k].joint].name) << ": "
        << num(a.joints[k].direction_speed);
    y << "}\n";
  }
  y << "thumb_links: [";
  for (size_t k = 0; k < hand.thumb_links.size(); ++k)
    y << (k ? ", " : "") << quoted(hand.links[hand.thumb_links[k]].name);
  y << "]\n";
  if (hand.soft_finger_radius_m > 0)
    y << "soft_finger_radius_m: " << num(hand.soft_finger_radius_m) << "\n";
  draft.yaml = y.str();
  return draft;
}

}  // namespace cordgrasp
