#include "cordgrasp/core/hand_conventions.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cordgrasp/core/geometry_points.h"
#include "cordgrasp/core/hand_fingers.h"
#include "cordgrasp/core/kinematics.h"

namespace cordgrasp {
namespace {

std::string quoted(const std::string& s) { return "'" + s + "'"; }

/// Centroid of the collision points of the links no actor moves (the palm), world frame; false
/// when there is none.
bool palm_centroid(const HandModel& hand, const std::vector<Finger>& fingers,
                   const std::vector<Eigen::Isometry3d>& X_WL, Eigen::Vector3d& out) {
  std::vector<bool> moved(hand.links.size(), false);
  for (const Finger& f : fingers)
    for (int l : f.links) moved[l] = true;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int n = 0;
  std::vector<Eigen::Vector3d> pts;
  for (size_t l = 0; l < hand.links.size(); ++l) {
    if (moved[l]) continue;
    pts.clear();
    append_collision_points(hand.links[l], pts);
    for (const auto& p : pts) {
      sum += X_WL[l] * p;
      ++n;
    }
  }
  if (n == 0) return false;
  out = sum / n;
  return true;
}

}  // namespace

Eigen::VectorXd advance_actor(const HandModel& hand, const Actor& actor, const Eigen::VectorXd& q,
                              double step) {
  Eigen::VectorXd out = q;
  for (const auto& e : actor.joints) out[e.joint] += step * e.direction_speed;
  return clamp_to_limits(hand, apply_couplings(hand, clamp_to_limits(hand, out)));
}

std::vector<std::string> check_hand_conventions(const HandModel& hand,
                                                const HandConventionParams& params) {
  std::vector<std::string> problems;
  auto say = [&](const std::string& s) { problems.push_back(hand.name + ": " + s); };
  const Eigen::VectorXd q0 = apply_couplings(hand, hand.preshape);
  const auto X0 = link_poses(hand, q0);
  const Eigen::Isometry3d X_WG = gcp_pose(hand, X0);
  const Eigen::Isometry3d X_GW = X_WG.inverse();
  const std::vector<Finger> fingers = hand_fingers(hand);
  if (fingers.empty()) {
    say("no actor moves any geometry (no fingers)");
    return problems;
  }

  // The palm behind the GCP.
  Eigen::Vector3d palm_W;
  const bool has_palm = palm_centroid(hand, fingers, X0, palm_W);
  if (!has_palm) {
    say("no static geometry (no palm)");
  } else if ((X_GW * palm_W).z() >= 0.0) {
    say("the palm is not behind the GCP (GCP +z must point from the palm into the grasp)");
  }

  // Thumb opposite the other fingertips about the GCP axis.
  Eigen::Vector2d thumb = Eigen::Vector2d::Zero(), others = Eigen::Vector2d::Zero();
  int n_thumb = 0, n_others = 0;
  for (const Finger& f : fingers) {
    if (f.tip_link < 0) continue;
    const Eigen::Vector2d xy = (X_GW * (X0[f.tip_link] * f.p_tip_L)).head<2>();
    (f.is_thumb ? thumb : others) += xy;
    (f.is_thumb ? n_thumb : n_others) += 1;
  }
  if (n_thumb != 1) {
    say(std::to_string(n_thumb) + " fingers hold the thumb links (exactly one should)");
  } else if (n_others == 0) {
    say("no finger besides the thumb");
  } else if (thumb.dot(others / n_others) >= 0.0) {
    say("thumb tip and fingertips are not on opposite sides of the GCP axis");
  }

  // Actors close towards the GCP: somewhere in its closing sweep each fingertip comes nearer the
  // GCP axis (a long digit may cross it within closing_step, a short one needs more), or ahead
  // along it; advanced by closing_step, it is nearer the GCP.
  struct ClosingTip {
    Eigen::Vector3d p_W, moved_W;  // advanced by closing_step; its motion
    std::string name;
  };
  std::vector<ClosingTip> closing_tips;
  for (size_t a = 0; a < hand.actors.size(); ++a) {
    const Actor& actor = hand.actors[a];
    const auto X1 = link_poses(hand, advance_actor(hand, actor, q0, params.closing_step));
    // The sweep: in steps of sweep_step until the actor's revolute joints (their <mimic>
    // followers included) have turned max_curl_rad in all, or closing_range.
    double turn_per_unit = 0.0;
    for (const auto& e : actor.joints) {
      const Joint& joint = hand.joints[e.joint];
      if (joint.type != JointType::kPrismatic) turn_per_unit += std::abs(e.direction_speed);
      for (const Joint& follower : hand.joints)
        if (follower.mimic && follower.mimic->master_joint == e.joint &&
            follower.type != JointType::kPrismatic)
          turn_per_unit += std::abs(follower.mimic->multiplier * e.direction_speed);
    }
    const double range = turn_per_unit > 0.0
                             ? std::min(params.closing_range, params.max_curl_rad / turn_per_unit)
                             : params.closing_range;
    const int steps = std::max(1, static_cast<int>(std::ceil(range / params.sweep_step - 1e-9)));
    std::vector<std::vector<Eigen::Isometry3d>> sweep;
    for (int k = 1; k <= steps; ++k)
      sweep.push_back(
          link_poses(hand, advance_actor(hand, actor, q0, std::min(range, k * params.sweep_step))));
    int n = 0;
    for (const Finger& f : fingers) {
      if (f.actor != static_cast<int>(a) || f.tip_link < 0) continue;
      ++n;
      const Eigen::Vector3d p1_W = X1[f.tip_link] * f.p_tip_L;
      const Eigen::Vector3d t0 = X_GW * (X0[f.tip_link] * f.p_tip_L);
      const Eigen::Vector3d t1 = X_GW * p1_W;
      const std::string tip = "actor " + quoted(actor.name) + ": tip on " +
                              quoted(hand.links[f.tip_link].name);
      // Into the grasp: nearer the axis, or ahead along +z and not farther from the axis (a
      // finger beside the axis at the GCP's height curls past it), or nearer the GCP (a thumb
      // beside the axis closing towards the palm).
      double nearer = 0.0, ahead = 0.0, closer = 0.0;
      for (const auto& X : sweep) {
        const Eigen::Vector3d t = X_GW * (X[f.tip_link] * f.p_tip_L);
        const double gain = t0.head<2>().norm() - t.head<2>().norm();
        nearer = std::max(nearer, gain);
        closer = std::max(closer, t0.norm() - t.norm());
        if (gain >= 0.0) ahead = std::max(ahead, t.z() - t0.z());
      }
      if (!(nearer >= params.min_closing_m) && !(ahead >= params.min_closing_m) &&
          !(closer >= params.min_closing_m)) {
        std::ostringstream s;
        s << tip << " does not close towards the GCP axis (at best " << nearer * 1e3
          << " mm nearer it, " << ahead * 1e3 << " mm ahead along it, " << closer * 1e3
          << " mm nearer the GCP)";
        say(s.str());
      }
      closing_tips.push_back({p1_W, p1_W - X0[f.tip_link] * f.p_tip_L, tip});
      if (!(t1.norm() < t0.norm())) say(tip + " moves away from the GCP");
    }
    if (n == 0) say("actor " + quoted(actor.name) + " moves no geometry");
  }

  // The palm normal points from the palm towards the closing region: the GCP lies in front of
  // the palm, and no fingertip closes backwards to behind it.
  if (hand.palm_normal && has_palm) {
    const PalmNormal& pn = *hand.palm_normal;
    if (pn.link < 0 || pn.link >= static_cast<int>(hand.links.size())) {
      say("palm normal on a link the hand does not have");
    } else {
      const Eigen::Vector3d n_W = X0[pn.link].linear() * pn.n_L;
      if (std::abs(n_W.norm() - 1.0) > 1e-9) say("palm normal is not a unit vector");
      const double gcp_height = (X_WG.translation() - palm_W).dot(n_W);
      if (!(gcp_height > 0.0))
        say("palm normal: the GCP is not in front of the palm (" + std::to_string(gcp_height) +
            " m along it)");
      for (const ClosingTip& t : closing_tips) {
        const double height = (t.p_W - palm_W).dot(n_W);
        if (!(height > 0.0) && !(t.moved_W.dot(n_W) > 0.0))
          say("palm normal: " + t.name + " closes backwards to behind the palm (" +
              std::to_string(height) + " m along it)");
      }
    }
  }
  return problems;
}

}  // namespace cordgrasp
