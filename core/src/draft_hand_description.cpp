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
#include "cordgrasp/core/palm_width.h"
#include "cordgrasp/core/parallel_for.h"
#include "cordgrasp/core/plan_cord_grasps.h"
#include "cordgrasp/core/shapes.h"
#include "fingertip_meeting_point.h"
#include "urdf_import.h"

namespace fs = std::filesystem;

namespace cordgrasp {
namespace {

/// A joint closes its finger when the tip moves at least this much along the closing direction
/// (cosine of the angle between the tip velocity and that direction).
constexpr double kMinClosingCosine = 0.5;
/// A thumb joint whose tip motion has at least this cosine with the direction to the other
/// fingertips (or its reverse) closes with that sign, whatever the palm's side adds.
constexpr double kThumbSignCosine = 0.25;
/// Opposed digits' closing joints open by at most this much in the drafted preshape [rad].
constexpr double kOpenOpposed_rad = M_PI / 4;
/// Finite-difference step for tip velocities [rad or m].
constexpr double kStep = 1e-3;
/// Revolute limits count as asymmetric (a flexion joint) when the larger side exceeds the
/// smaller by this fraction of the range.
constexpr double kAsymmetry = 0.2;
/// A digit opposes along an axis when its closing motion has at least this cosine with it.
constexpr double kOpposingCosine = 0.5;
/// Two joint axes of a finger flex it the same way when their cosine is at least this.
constexpr double kSameAxisCosine = 0.7;
/// A joint axis counts as across its finger when |axis × extension| is at least this.
constexpr double kMinAcross = 0.7;
/// Fingers with two-sided limits flex towards the thumb's side of the palm when the thumb tip
/// lies at least this far off the palm's centre across the fingers' joint axes [m].
constexpr double kMinThumbSide_m = 0.005;
/// The thumb by position is ambiguous below this confidence; then the digit whose closing
/// motion is the most against the others' is the thumb, when it is so by this much more
/// (difference of cosines) than the thumb by position.
constexpr double kAmbiguousThumb = 0.25;
constexpr double kClearlyMoreAgainst = 0.3;
/// Fingers in a row point the same way at rest: their extensions' cosine is at least this; an
/// ambiguous thumb is the one digit whose cosine with each of them is lower by the margin.
constexpr double kParallelFingersCosine = 0.95;
constexpr double kOddThumbMargin = 0.2;
/// A digit's joints close together by at most this much in the meeting-point sweep [rad]: a
/// straight digit then points across the palm.
constexpr double kMaxCurl_rad = M_PI / 2;
/// Digits oppose across the palm when the roots of those closing one way lie from the roots of
/// those closing the other way along the closing axis, at least this cosine.
constexpr double kRootsApartCosine = 0.85;
/// ... and when the palm's centroid lies between their roots along that axis, at least this
/// fraction of the way from either side.
constexpr double kPalmBetween = 1.0 / 3.0;
/// The roots' plane normal, or the digits' flexing joint axis, lies across the closing axis
/// when its cosine with it is at most this.
constexpr double kAcrossClosingAxisCosine = 0.3;
/// Two digits' roots stand apart (jaw to jaw) at least this far [m].
constexpr double kMinRootsApart_m = 0.01;
/// Confidence in a thumb found alone on its side of opposed digits, at least (the side is
/// clear; which digit a user calls the thumb is not).
constexpr double kLoneThumbConfidence = 0.5;

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

/// A length in metres written in millimetres to 0.1 mm.
std::string mm(double v_m) { return num(std::round(v_m * 1e4) / 10.0) + " mm"; }

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

/// How finger f closes, for the meeting-point sweep: each own revolute joint with one-sided
/// limits goes to its larger side; one with symmetric limits to the side that moves the tip
/// towards `others_W` (the other fingertips' centroid), when it moves the tip mostly that way.
hand_draft::ClosingDigit closing_digit(const HandModel& hand, const DraftFinger& f,
                                       const Eigen::VectorXd& q0, const Eigen::Vector3d& tip_W,
                                       const Eigen::Vector3d& others_W) {
  hand_draft::ClosingDigit d;
  d.tip_link = f.tip_link;
  d.p_tip_L = f.p_tip_L;
  for (int j : f.joints) {
    const Joint& joint = hand.joints[j];
    if (joint.type != JointType::kRevolute) continue;
    const double up = joint.upper - q0[j], down = q0[j] - joint.lower;
    if (std::abs(up - down) >= kAsymmetry * (joint.upper - joint.lower)) {
      d.closed_q.push_back({j, up > down ? joint.upper : joint.lower});
      continue;
    }
    const Eigen::Vector3d v = tip_velocity(hand, f, q0, j);
    const Eigen::Vector3d towards = others_W - tip_W;
    if (v.norm() < 1e-9 || towards.norm() < 1e-9) continue;
    const double c = v.normalized().dot(towards.normalized());
    if (std::abs(c) >= kMinClosingCosine)
      d.closed_q.push_back({j, c > 0 ? joint.upper : joint.lower});
  }
  // Mid-closure: the digit curls at most kMaxCurl_rad in all (its <mimic> joints included), so
  // that a long digit's tip is not swept back into the palm.
  double curl = 0.0;
  for (const auto& [j, closed] : d.closed_q) curl += std::abs(closed - q0[j]);
  for (const Joint& joint : hand.joints) {
    if (!joint.mimic ||
        std::find(f.links.begin(), f.links.end(), joint.child_link) == f.links.end())
      continue;
    for (const auto& [j, closed] : d.closed_q)
      if (j == joint.mimic->master_joint)
        curl += std::abs(joint.mimic->multiplier * (closed - q0[j]));
  }
  if (curl > kMaxCurl_rad)
    for (auto& [j, closed] : d.closed_q) closed = q0[j] + (closed - q0[j]) * kMaxCurl_rad / curl;
  return d;
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

/// Test planning of a drafted GCP's place (draft_hand_description with a collider): spheres and
/// cylinders sized to the palm width (the planner's own scale), GCP places shifted sideways, a
/// few finger-stage attempts on each.
constexpr double kTestDiametersRel[] = {0.3, 0.5, 0.7};  ///< of the palm width
constexpr double kTestCylinderLengthRel = 1.5;           ///< of the palm width
constexpr double kGcpShiftRel = 0.15;  ///< sideways shift of a candidate place, of the palm width
constexpr int kTestAttempts = 24;      ///< finger-stage attempts per place and shape
/// A shifted place is kept over the drafted one when it finds at least this many times as many
/// force-closure grasps and this many more.
constexpr double kMinGainRel = 1.25;
constexpr int kMinGainGrasps = 3;
constexpr double kTestTimeLimit_s = 60.0;  ///< per place and shape: a cap, the attempts decide

/// Force-closure grasps found by test planning with the GCP shifted by each of `shifts_G` (in
/// its own frame; the first is the drafted place), summed over the test shapes, which are
/// planned on up to `threads` threads. A place that fails more of the conventions than the
/// drafted one is not tried and scores -1.
std::vector<int> test_plan_gcp_places(const HandModel& hand,
                                      const std::vector<Eigen::Vector3d>& shifts_G,
                                      double palm_width_m, const MakeCollider& make_collider,
                                      int threads) {
  std::vector<Mesh> shapes;
  for (double d : kTestDiametersRel) {
    shapes.push_back(make_sphere_mesh(0.5 * d * palm_width_m));
    shapes.push_back(
        make_cylinder_mesh(0.5 * d * palm_width_m, kTestCylinderLengthRel * palm_width_m));
  }
  const size_t drafted_problems = check_hand_conventions(hand).size();
  std::vector<HandModel> places(shifts_G.size(), hand);
  std::vector<bool> tried(shifts_G.size(), true);
  for (size_t c = 0; c < shifts_G.size(); ++c) {
    Eigen::Isometry3d& X_LG = places[c].gcp.X_LG;
    X_LG.translation() += X_LG.linear() * shifts_G[c];
    tried[c] = check_hand_conventions(places[c]).size() <= drafted_problems;
  }
  PlanParams params;
  params.grasps = kTestAttempts;
  params.max_attempts = kTestAttempts;
  params.fallback_attempts = 0;  // the cord planner's placement is what a place is judged by
  params.time_limit_s = kTestTimeLimit_s;
  params.quality.contact.soft_finger_radius_m = hand.soft_finger_radius_m;  // as `plan` does
  std::vector<std::vector<int>> found(shapes.size(), std::vector<int>(places.size(), 0));
  parallel_for(int(shapes.size()), threads, [&](int s) {
    // The collider holds the links' shapes only: one serves every GCP place.
    const std::unique_ptr<HandObjectCollider> collider = make_collider(hand, shapes[s]);
    for (size_t c = 0; c < places.size(); ++c)
      if (tried[c])
        found[s][c] = plan_cord_grasps(shapes[s], places[c], *collider, CordParams{}, params)
                          .stats.force_closure;
  });
  std::vector<int> total(places.size(), -1);  // -1: a place not tried
  for (size_t c = 0; c < places.size(); ++c) {
    if (!tried[c]) continue;
    total[c] = 0;
    for (const auto& per_shape : found) total[c] += per_shape[c];
  }
  return total;
}

}  // namespace

HandDraft draft_hand_description(const std::string& urdf_path, const std::string& out_path,
                                 const HandLoadOptions& options, const MakeCollider& make_collider,
                                 int threads) {
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
  // The palm: collision points of the links outside the fingers.
  std::vector<Eigen::Vector3d> palm_pts;
  Eigen::Vector3d palm_c = Eigen::Vector3d::Zero();
  {
    std::vector<bool> in_finger(hand.links.size(), false);
    for (const DraftFinger& f : fingers)
      for (int l : f.links) in_finger[l] = true;
    std::vector<Eigen::Vector3d> pts;
    for (size_t l = 0; l < hand.links.size(); ++l) {
      if (in_finger[l]) continue;
      pts.clear();
      append_collision_points(hand.links[l], pts);
      for (const auto& p : pts) palm_pts.push_back(X0[l] * p);
    }
    for (const auto& p : palm_pts) palm_c += p / double(palm_pts.size());
  }
  // The fingertips' meeting point: every digit closes (one-sided joints to their larger side)
  // and the fingertips come closest together somewhere in front of the palm.
  Eigen::Vector3d roots_c = Eigen::Vector3d::Zero(), tips_sum = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < nf; ++i) {
    roots_c += roots[i] / double(nf);
    tips_sum += tips[i];
  }
  std::vector<hand_draft::ClosingDigit> closing;
  for (size_t i = 0; i < nf; ++i) {
    const Eigen::Vector3d others = nf > 1 ? Eigen::Vector3d((tips_sum - tips[i]) / double(nf - 1))
                                          : tips[i];
    closing.push_back(closing_digit(hand, fingers[i], hand.preshape, tips[i], others));
  }
  const hand_draft::MeetingPoint meet =
      hand_draft::fingertip_meeting_point(hand, hand.preshape, closing);
  // Each digit's closing motion: the way its fingertip starts closing.
  std::vector<Eigen::Vector3d> closing_motion(nf, Eigen::Vector3d::Zero());
  if (meet.found) closing_motion = meet.start_motion_W;

  // Flexing joints of finger i: revolute, one-sided limits, the axis along the most distal such
  // joint's (one across it, a Barrett-like spread, turns the finger sideways).
  auto one_sided = [&](int j) {
    const Joint& joint = hand.joints[j];
    const double up = joint.upper - q0[j], down = q0[j] - joint.lower;
    return joint.type == JointType::kRevolute &&
           std::abs(up - down) >= kAsymmetry * (joint.upper - joint.lower);
  };
  auto axis_W = [&](int j) {
    return Eigen::Vector3d(X0[hand.joints[j].child_link].linear() * hand.joints[j].axis);
  };
  auto flexing_joints = [&](size_t i) {
    Eigen::Vector3d distal_axis = Eigen::Vector3d::Zero();
    for (int j : fingers[i].joints)
      if (one_sided(j)) distal_axis = axis_W(j);
    std::vector<int> out;
    for (int j : fingers[i].joints)
      if (one_sided(j) && std::abs(axis_W(j).dot(distal_axis)) >= kSameAxisCosine) out.push_back(j);
    return out;
  };
  // Extension of finger i: from its first flexing joint (else its root) to its centroid.
  auto finger_extension = [&](size_t i) {
    const std::vector<int> flexing = flexing_joints(i);
    const Eigen::Vector3d base =
        flexing.empty() ? roots[i] : X0[hand.joints[flexing.front()].child_link].translation();
    return Eigen::Vector3d((centres[i] - base).normalized());
  };
  // Flexion of finger i: each flexing joint's tip motion towards its larger side, across the
  // finger's extension and the joint axis (a fingertip off the finger's centre line, a bent
  // distal link, does not tilt it).
  auto finger_flexion = [&](size_t i) {
    Eigen::Vector3d flexion = Eigen::Vector3d::Zero();
    const Eigen::Vector3d e = finger_extension(i);
    for (int j : flexing_joints(i)) {
      const Joint& joint = hand.joints[j];
      const double up = joint.upper - q0[j], down = q0[j] - joint.lower;
      Eigen::Vector3d v = tip_velocity(hand, fingers[i], q0, j);
      v -= v.dot(e) * e;  // without the finger's own extension
      const Eigen::Vector3d across = axis_W(j).cross(e);
      if (across.norm() > kMinAcross && v.norm() > 1e-9)
        v = (v.dot(across) >= 0 ? 1.0 : -1.0) * across;
      if (v.norm() > 1e-9) flexion += (up > down ? 1.0 : -1.0) * v.normalized();
    }
    return flexion;
  };
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
  // Opposition: the digit whose closing motion points most against the others' is the thumb
  // when the layout alone cannot tell (two digits on each side, say).
  std::string thumb_why = nf == 2 ? "two fingers: either opposes the other"
                                  : "root and tip farthest from the other fingers'";
  if (meet.found && nf > 2) {
    Eigen::Vector3d all_motion = Eigen::Vector3d::Zero();
    for (const auto& m : closing_motion) all_motion += m;
    std::vector<double> against(nf, 0.0);
    for (size_t i = 0; i < nf; ++i) {
      const Eigen::Vector3d rest = all_motion - closing_motion[i];
      if (closing_motion[i].norm() > 1e-9 && rest.norm() > 1e-9)
        against[i] = -closing_motion[i].normalized().dot(rest.normalized());
    }
    const int most = int(std::max_element(against.begin(), against.end()) - against.begin());
    std::ostringstream why;
    why << std::fixed << std::setprecision(2);
    if (most == thumb) {
      why << thumb_why << "; its closing motion is the most against the others' (cosine "
          << -against[thumb] << ")";
      confidence_thumb = std::max(confidence_thumb, std::min(0.9, 0.5 * against[thumb]));
    } else if (confidence_thumb < kAmbiguousThumb && against[most] >= kOpposingCosine &&
               against[most] - against[thumb] >= kClearlyMoreAgainst &&
               !fingers[most].driven_elsewhere) {
      why << "its closing motion points against the others' (cosine " << -against[most]
          << "; '" << finger_name(hand, fingers[thumb]) << "', farthest from the others, "
          << -against[thumb] << ")";
      thumb = most;
      confidence_thumb = std::min(0.9, 0.5 * against[most]);
    } else {
      why << thumb_why << "; but '" << finger_name(hand, fingers[most])
          << "' closes more against the others (cosine " << -against[most] << " vs "
          << -against[thumb] << ")";
      confidence_thumb *= 0.5;
    }
    thumb_why = why.str();
  }
  // Direction: fingers standing in a row point the same way at rest and the thumb does not.
  // Two digits that close against each other look alike to the opposition test above; the
  // one that points elsewhere than a row of parallel others is the thumb.
  if (nf > 2 && confidence_thumb < kAmbiguousThumb) {
    std::vector<Eigen::Vector3d> e(nf);
    for (size_t i = 0; i < nf; ++i) e[i] = finger_extension(i);
    const hand_draft::OddDirection o =
        hand_draft::odd_direction_out_of_row(e, kParallelFingersCosine, kOddThumbMargin);
    const int odd = o.index;
    const double odd_cosine = o.cosine;
    if (odd >= 0 && !fingers[odd].driven_elsewhere) {
      std::ostringstream why;
      why << std::fixed << std::setprecision(2);
      if (odd != thumb)
        why << "the other fingers point the same way at rest and it does not (cosine " << odd_cosine
            << "); '" << finger_name(hand, fingers[thumb]) << "': " << thumb_why;
      else
        why << thumb_why << "; and it points elsewhere than the other fingers (cosine "
            << odd_cosine << ")";
      thumb = odd;
      confidence_thumb = std::max(confidence_thumb, std::min(0.9, 1.0 - odd_cosine));
      thumb_why = why.str();
    }
  }
  guess("thumb", finger_name(hand, fingers[thumb]), confidence_thumb, thumb_why);

  // Palm normal: the non-thumb fingers' flexion direction (joints with asymmetric limits,
  // towards the larger side), without its component along the fingers' extension.
  Eigen::Vector3d extension = Eigen::Vector3d::Zero(), flexion = Eigen::Vector3d::Zero();
  Eigen::Vector3d others_tips = Eigen::Vector3d::Zero();
  int n_others = 0;
  // Fingers that flex against each other (opposed digits, the thumb among them mistaken for a
  // finger) share the axis, not the side: each counts along the first one's side.
  bool flexions_oppose = false;
  for (size_t i = 0; i < nf; ++i) {
    if (int(i) == thumb) continue;
    extension += finger_extension(i);
    others_tips += tips[i];
    ++n_others;
    Eigen::Vector3d f = finger_flexion(i);
    if (f.norm() > 1e-9 && flexion.norm() > 1e-9 &&
        f.normalized().dot(flexion.normalized()) < -kOpposingCosine) {
      f = -f;
      flexions_oppose = true;
    }
    flexion += f;
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
  bool from_flexion = true;
  if (normal_W.norm() < 1e-6 && nf > 2) {
    // No one-sided limits (every finger joint ±90°, say): the fingers still flex across their
    // joint axes, and towards the side of the palm the thumb stands on (a thumb opposes from
    // the palm's front).
    Eigen::Vector3d axis = Eigen::Vector3d::Zero();
    int across_joints = 0;
    bool revolute = true;
    for (size_t i = 0; i < nf; ++i) {
      if (int(i) == thumb) continue;
      const Eigen::Vector3d e = finger_extension(i);
      for (int j : fingers[i].joints) {
        if (hand.joints[j].type != JointType::kRevolute) {
          revolute = false;
          continue;
        }
        Eigen::Vector3d across = axis_W(j).cross(e);
        if (across.norm() < kMinAcross) continue;
        across.normalize();
        axis += across.dot(axis) >= 0.0 ? across : Eigen::Vector3d(-across);
        ++across_joints;
      }
    }
    axis -= axis.dot(extension) * extension;
    const double thumb_side_m =
        axis.norm() > 1e-9 ? (tips[thumb] - palm_c).dot(axis.normalized()) : 0.0;
    if (revolute && across_joints > 0 && axis.norm() >= kSameAxisCosine * across_joints &&
        std::abs(thumb_side_m) >= kMinThumbSide_m) {
      normal_W = (thumb_side_m > 0.0 ? 1.0 : -1.0) * axis.normalized();
      confidence_normal = 0.5;
      normal_why =
          "no one-sided joint limits: across the fingers' joint axes, towards the "
          "thumb's side of the palm (its tip " +
          num(std::round(std::abs(thumb_side_m) * 1000)) + " mm off the palm's centre)";
    }
  }
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
        // Jaw to jaw: between the digits' roots when they stand apart (revolute digits of
        // unequal lengths have their centroids at unequal heights), else their centroids.
        const bool roots_apart = (roots[1] - roots[0]).norm() >= kMinRootsApart_m;
        const Eigen::Vector3d jaw =
            (roots_apart ? roots[1] - roots[0] : centres[1] - centres[0]).normalized();
        normal_W -= normal_W.dot(jaw) * jaw;
      }
    }
    confidence_normal = 0.7;
    normal_why = "no flexion joints: along the fingers";
    from_flexion = false;
  }
  normal_W.normalize();
  // Second witness: where the fingertips meet. Digits that close towards each other across the
  // palm (opposed digits standing up from it: the palm lies between them along their closing
  // axis) make the flexion the opposition axis, not the palm normal: the normal is then the
  // direction from the digits' roots to the meeting point, without its component along that
  // axis. Otherwise the meeting point must lie in front of the palm along the flexion normal.
  bool opposed = false;
  Eigen::Vector3d opposition_W = Eigen::Vector3d::Zero();
  hand_draft::Opposition opposition;  ///< the digits on either side, when opposed
  if (meet.found) {
    const Eigen::Vector3d w = meet.p_W - roots_c;
    // The closing axis: the flexion, or without flexion joints the digits' main closing motion.
    const Eigen::Vector3d axis_W =
        from_flexion ? normal_W : hand_draft::main_closing_axis(closing_motion);
    const hand_draft::Opposition o = hand_draft::opposition_across(axis_W, roots, closing_motion,
                                                                   palm_c, kOpposingCosine);
    const Eigen::Vector3d n = w - w.dot(axis_W) * axis_W;
    std::ostringstream meets;
    meets << "the fingertips meet at " << num(std::round(meet.closure * 100)) << " % closure";
    if (o.roots_apart_cosine >= kRootsApartCosine && o.palm_between >= kPalmBetween &&
        o.palm_between <= 1.0 - kPalmBetween && n.norm() > 1e-6) {
      opposed = true;
      opposition_W = axis_W;
      opposition = o;
      confidence_normal = std::min(confidence_normal, n.norm() / w.norm());
      normal_W = n.normalized();
      normal_why = std::to_string(o.along.size()) + " digits close towards " +
                   std::to_string(o.against.size()) +
                   " across the palm between them: from the digits' roots to where " + meets.str() +
                   " (" + num(std::round(w.norm() * 1000)) + " mm), across that closing axis";
      // Three or more roots spread over the palm's face span it: its normal is theirs, on the
      // side where the fingertips meet (digits of unequal lengths meet off the roots' centre).
      const hand_draft::RootsPlane plane = hand_draft::roots_plane(roots);
      // Fewer roots: digits curl across their flexing joints' axes, so the normal lies across
      // both that axis and the closing axis (the meeting point of fingertips on box corners
      // lies off that plane).
      Eigen::Vector3d joint_axis = Eigen::Vector3d::Zero();
      for (size_t i = 0; i < nf; ++i)
        for (int j : flexing_joints(i)) {
          const Eigen::Vector3d a = X0[hand.joints[j].child_link].linear() * hand.joints[j].axis;
          joint_axis += a.dot(joint_axis) >= 0.0 ? a : Eigen::Vector3d(-a);
        }
      if (plane.found && std::abs(plane.normal_W.dot(axis_W)) <= kAcrossClosingAxisCosine) {
        Eigen::Vector3d m = plane.normal_W - plane.normal_W.dot(axis_W) * axis_W;
        if (m.dot(normal_W) < 0.0) m = -m;
        normal_W = m.normalized();
        normal_why += "; the normal of the plane of the " + std::to_string(nf) +
                      " digits' roots, on that side";
      } else if (joint_axis.norm() > 1e-9 &&
                 std::abs(joint_axis.normalized().dot(axis_W)) <= kAcrossClosingAxisCosine) {
        Eigen::Vector3d m = axis_W.cross(joint_axis).normalized();
        if (m.dot(normal_W) < 0.0) m = -m;
        normal_W = m;
        normal_why += "; across the digits' flexing joint axes, on that side";
      }
    } else {
      double ahead_m = (meet.p_W - palm_c).dot(normal_W);
      if (flexions_oppose && ahead_m < 0.0) {  // the flexion axis has no side of its own
        normal_W = -normal_W;
        ahead_m = -ahead_m;
        normal_why += " (fingers flexing against each other: the side where they meet)";
      }
      meets << " " << num(std::round(ahead_m * 1000)) << " mm in front of the palm along it";
      if (ahead_m > 0.0) {
        normal_why += "; " + meets.str();
      } else {
        confidence_normal *= 0.5;
        normal_why += "; but " + meets.str() + ": check";
      }
    }
  } else {
    normal_why += "; no fingertip meeting point (the digits do not close towards each other)";
  }
  const Eigen::Matrix3d R_WP = X0[palm].linear();
  hand.palm_normal = PalmNormal{palm, R_WP.transpose() * normal_W};
  guess("palm normal", "'" + hand.links[palm].name + "' " + vec(hand.palm_normal->n_L),
        confidence_normal, normal_why);

  // Opposed digits, one of them alone on its side of the closing axis: that one is the thumb
  // (a thumb beside another digit has no side of its own to oppose from).
  if (opposed && nf > 2) {
    const std::vector<int>& along = opposition.along;
    const std::vector<int>& against = opposition.against;
    int lone = -1;
    if (along.size() == 1 && against.size() > 1) lone = along.front();
    if (against.size() == 1 && along.size() > 1) lone = against.front();
    if (lone >= 0 && lone != thumb && !fingers[lone].driven_elsewhere) {
      const auto it = std::find_if(draft.guesses.begin(), draft.guesses.end(),
                                   [](const DraftGuess& g) { return g.what == "thumb"; });
      it->value = finger_name(hand, fingers[lone]);
      it->confidence = std::max(it->confidence, kLoneThumbConfidence);
      it->why = "alone on its side of the opposed digits' closing axis; '" +
                finger_name(hand, fingers[thumb]) + "' first: " + it->why;
      thumb = lone;
      others_tips = Eigen::Vector3d::Zero();
      for (size_t i = 0; i < nf; ++i)
        if (int(i) != thumb) others_tips += tips[i] / double(nf - 1);
    }
  }

  // Closing joints and their signs.
  const Eigen::Vector3d thumb_tip = tips[thumb];
  for (size_t i = 0; i < nf; ++i) {
    const DraftFinger& f = fingers[i];
    if (f.driven_elsewhere || f.joints.empty()) continue;
    const bool is_thumb = int(i) == thumb;
    Actor actor;
    actor.name = is_thumb ? "thumb" : finger_name(hand, f);
    double worst = 1.0;
    std::vector<double> closing_cosine;  // per listed joint
    std::ostringstream listed;
    // Of two digits, one whose joints do not move its tip along the palm normal closes towards
    // the other, as the thumb does (jaws on joints with two-sided limits).
    const int passes = nf == 2 && !is_thumb ? 2 : 1;
    bool closes_to_other = is_thumb;
    for (int pass = 0; pass < passes && actor.joints.empty(); ++pass) {
      const bool to_other = is_thumb || pass == 1;
      closes_to_other = to_other;
      for (int j : f.joints) {
        const Joint& joint = hand.joints[j];
        const Eigen::Vector3d v = tip_velocity(hand, f, q0, j);
        if (v.norm() < 1e-9) continue;
        Eigen::Vector3d towards = normal_W;
        if (joint.type == JointType::kPrismatic || to_other) {
          const Eigen::Vector3d target = is_thumb ? others_tips : thumb_tip;
          towards = target - tips[i];
          if (joint.type == JointType::kPrismatic && nf == 2) towards = tips[1 - i] - tips[i];
          towards -= towards.dot(normal_W) * normal_W;
          if (towards.norm() < 1e-9) continue;
          towards.normalize();
        }
        if (opposed && joint.type == JointType::kRevolute) {
          // Opposed digits close across the palm, towards where the fingertips meet.
          towards = (meet.p_W - tips[i]).dot(opposition_W) >= 0 ? opposition_W : -opposition_W;
        }
        double c = v.normalized().dot(towards);
        if ((to_other || opposed) && joint.type != JointType::kPrismatic) {
          // A revolute thumb closes towards the others, or towards them and the palm's front, or
          // (not opposed) towards them and the palm: a human-like thumb standing out of the palm
          // face closes up it and back towards it. When the tip clearly moves towards or away
          // from the others, that decides the sign; the palm's side only adds confidence.
          const double c2 = v.normalized().dot((towards + normal_W).normalized());
          const bool sign_of_c = is_thumb && !opposed && std::abs(c) >= kThumbSignCosine;
          const double c3 = sign_of_c ? v.normalized().dot((towards - normal_W).normalized()) : 0.0;
          for (const double ci : {c2, c3})
            if (std::abs(ci) > std::abs(c) && (!sign_of_c || ci * c > 0.0)) c = ci;
        }
        if (std::abs(c) < kMinClosingCosine) continue;
        const double speed =
            (c > 0 ? 1.0 : -1.0) * (joint.type == JointType::kPrismatic ? 0.1 : 1.0);
        actor.joints.push_back({j, speed});
        closing_cosine.push_back(std::abs(c));
        worst = std::min(worst, std::abs(c));
      }
    }
    // A revolute thumb's joints about one axis curl it one way: the surest sets the sign of
    // the others (a distal joint's tip motion, from a box corner, can point the other way).
    if (is_thumb && !opposed && actor.joints.size() > 1) {
      const size_t sure = static_cast<size_t>(
          std::max_element(closing_cosine.begin(), closing_cosine.end()) -
          closing_cosine.begin());
      const Eigen::Vector3d ref = axis_W(actor.joints[sure].joint);
      const double ref_sign = actor.joints[sure].direction_speed > 0 ? 1.0 : -1.0;
      for (auto& e : actor.joints) {
        if (hand.joints[e.joint].type != JointType::kRevolute) continue;
        const double a = axis_W(e.joint).dot(ref);
        if (std::abs(a) >= kSameAxisCosine)
          e.direction_speed = std::abs(e.direction_speed) * ref_sign * (a > 0 ? 1.0 : -1.0);
      }
    }
    for (size_t k = 0; k < actor.joints.size(); ++k)
      listed << (k ? ", " : "") << hand.joints[actor.joints[k].joint].name
             << (actor.joints[k].direction_speed > 0 ? " +" : " -");
    // A thumb with more closing joints than two: its root joint turns it into opposition, when
    // it turns about another axis than the next one (else it flexes the thumb like them).
    if (is_thumb && actor.joints.size() > 2 && actor.joints.front().joint == f.joints.front() &&
        std::abs(axis_W(actor.joints[0].joint).dot(axis_W(actor.joints[1].joint))) <
            kSameAxisCosine) {
      actor.joints.erase(actor.joints.begin());
      listed.str("");
      for (size_t k = 0; k < actor.joints.size(); ++k)
        listed << (k ? ", " : "") << hand.joints[actor.joints[k].joint].name
               << (actor.joints[k].direction_speed > 0 ? " +" : " -");
      listed << " (root joint " << hand.joints[f.joints.front()].name << " left to the preshape)";
    }
    if (actor.joints.empty()) continue;
    guess("actor " + actor.name, listed.str(), worst,
          opposed    ? "tip moves across the palm towards where the fingertips meet"
          : is_thumb ? "tip moves towards the other fingertips"
          : closes_to_other
              ? "tip moves towards the other digit's (none of its joints along the palm normal)"
              : "tip moves along the palm normal");
    hand.actors.push_back(std::move(actor));
  }
  if (hand.actors.empty())
    throw InputError("hand init: '" + urdf_path + "': no joint closes any finger");
  for (int l : fingers[thumb].links) hand.thumb_links.push_back(l);
  // Prismatic closing joints start open: at the limit their closing motion leaves. Opposed
  // digits open away from where they meet, each closing joint to its limit or by at most
  // kOpenOpposed_rad, so that objects wider than their stance fit between them.
  Eigen::VectorXd q_open = q0;
  for (const Actor& a : hand.actors)
    for (const auto& e : a.joints) {
      const Joint& joint = hand.joints[e.joint];
      if (joint.type == JointType::kPrismatic)
        q_open[e.joint] = e.direction_speed > 0 ? joint.lower : joint.upper;
      else if (opposed && joint.type == JointType::kRevolute)
        q_open[e.joint] = e.direction_speed > 0
                              ? std::max(joint.lower, q0[e.joint] - kOpenOpposed_rad)
                              : std::min(joint.upper, q0[e.joint] + kOpenOpposed_rad);
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
  double palm_top = palm_pts.empty() ? 0.0 : -1e9;
  for (const auto& p : palm_pts) palm_top = std::max(palm_top, (p - palm_c).dot(normal_W));
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
  // Opposed digits: across the palm where the fingertips meet (the thumb side is not "the
  // others'" side when several digits stand on each).
  if (opposed) mid = meet.p_W + (mid - meet.p_W).dot(normal_W) * normal_W;
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
  // Opposed digits standing up from the palm: halfway from the palm's front to where the
  // fingertips meet.
  const double target_h =
      opposed   ? palm_top + 0.5 * ((meet.p_W - palm_c).dot(normal_W) - palm_top)
      : nf == 2 ? tips_top - 0.02
                : std::min(mid_h, palm_top - 0.015);
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
        "between thumb tip and fingertips, " + mm(best_h - palm_top) +
            " from the front of the palm's bounds along the palm normal");
  {
    int nonzero = 0;
    for (Eigen::Index j = 0; j < q_open.size(); ++j) nonzero += q_open[j] != 0.0;
    guess("preshape", nonzero ? std::to_string(nonzero) + " joints not at 0" : "all joints 0",
          0.5,
          std::string("the URDF's zero configuration clamped to the limits; prismatic jaws open") +
              (opposed ? "; opposed digits open away from where they meet (45° at most)" : ""));
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
  // Two digits (jaws, two-finger claws) close on their own line: no sideways place to choose.
  const double width = make_collider && nf > 2 ? palm_width(hand) : 0.0;
  if (width > 0.0) {
    const double d = kGcpShiftRel * width;
    const std::vector<Eigen::Vector3d> shifts = {
        Eigen::Vector3d::Zero(), {d, 0, 0}, {-d, 0, 0}, {0, d, 0}, {0, -d, 0}};
    const std::vector<int> found =
        test_plan_gcp_places(hand, shifts, width, make_collider, threads);
    // Another place replaces the drafted one only when it plans clearly more.
    size_t best = size_t(std::max_element(found.begin(), found.end()) - found.begin());
    if (found[best] < kMinGainRel * found[0] + kMinGainGrasps) best = 0;
    hand.gcp.X_LG.translation() += hand.gcp.X_LG.linear() * shifts[best];
    const char* const kPlaceNames[] = {"here", "+x", "-x", "+y", "-y"};
    std::string counts;
    for (size_t c = 0; c < found.size(); ++c)
      counts += (c ? ", " : "") + (found[c] < 0 ? std::string("-") : std::to_string(found[c]));
    const auto it =
        std::find_if(draft.guesses.begin(), draft.guesses.end(),
                     [](const DraftGuess& g) { return g.what == "gcp"; });  // made above
    it->value = "'" + hand.links[palm].name + "' xyz " + vec(hand.gcp.X_LG.translation());
    it->why +=
        std::string("; ") +
        (best == 0 ? std::string("kept") : "shifted " + mm(d) + " along " + kPlaceNames[best]) +
        " by test planning (spheres and cylinders 0.3-0.7 palm widths across, " +
        std::to_string(kTestAttempts) +
        " attempts each): force-closure grasps here, +x, -x, +y, -y: " + counts;
    if (found[best] > found[0]) it->confidence = std::max(it->confidence, 0.6);
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
      // Every digit: a joint limit rounded to 6 digits may lie outside the limits on load.
      std::ostringstream exact;
      exact << std::setprecision(17) << q_open[j];
      y << "  " << quoted(hand.joints[j].name) << ": " << exact.str() << "\n";
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
