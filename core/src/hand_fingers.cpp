#include "cordgrasp/core/hand_fingers.h"

#include <algorithm>

#include "cordgrasp/core/geometry_points.h"
#include "cordgrasp/core/kinematics.h"

namespace cordgrasp {

std::vector<Finger> hand_fingers(const HandModel& hand) {
  const size_t n_links = hand.links.size();
  const auto X_WL = link_poses(hand, apply_couplings(hand, hand.preshape));
  std::vector<Finger> fingers;
  for (size_t a = 0; a < hand.actors.size(); ++a) {
    // Joints the actor drives: its own and every joint coupled to one of them.
    std::vector<bool> driven(hand.joints.size(), false);
    for (const auto& e : hand.actors[a].joints) driven[e.joint] = true;
    for (size_t j = 0; j < hand.joints.size(); ++j)
      if (hand.joints[j].mimic && driven[hand.joints[j].mimic->master_joint]) driven[j] = true;
    // Links below a driven joint (joints are in topological order: one pass).
    std::vector<bool> moved(n_links, false);
    for (size_t j = 0; j < hand.joints.size(); ++j)
      if (driven[j] || moved[hand.joints[j].parent_link]) moved[hand.joints[j].child_link] = true;
    // One finger per chain root: a moved link whose parent link is not moved.
    for (size_t root = 0; root < n_links; ++root) {
      const int pj = hand.links[root].parent_joint;
      if (!moved[root] || pj < 0 || moved[hand.joints[pj].parent_link]) continue;
      Finger f;
      f.actor = static_cast<int>(a);
      std::vector<bool> in(n_links, false);
      in[root] = true;
      f.links.push_back(static_cast<int>(root));
      for (const Joint& j : hand.joints)
        if (in[j.parent_link] && !in[j.child_link]) {
          in[j.child_link] = true;
          f.links.push_back(j.child_link);
        }
      const Joint& root_joint = hand.joints[pj];
      const Eigen::Vector3d p_root = (X_WL[root_joint.parent_link] * root_joint.X_PJ).translation();
      double best = -1.0;
      for (int l : f.links) {
        f.is_thumb = f.is_thumb || std::find(hand.thumb_links.begin(), hand.thumb_links.end(), l) !=
                                       hand.thumb_links.end();
        std::vector<Eigen::Vector3d> pts;
        append_collision_points(hand.links[l], pts);
        for (const auto& p : pts) {
          const double d = (X_WL[l] * p - p_root).norm();
          if (d > best) {
            best = d;
            f.tip_link = l;
            f.p_tip_L = p;
          }
        }
      }
      fingers.push_back(std::move(f));
    }
  }
  return fingers;
}

}  // namespace cordgrasp
