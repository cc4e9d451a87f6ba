#include "cordgrasp/core/palm_width.h"

#include <limits>
#include <stdexcept>
#include <vector>

#include "cordgrasp/core/geometry_points.h"
#include "cordgrasp/core/hand_fingers.h"
#include "cordgrasp/core/kinematics.h"

namespace cordgrasp {

double measure_palm_width(const HandModel& hand) {
  const std::vector<Eigen::Isometry3d> X_WL =
      link_poses(hand, apply_couplings(hand, hand.preshape));
  const Eigen::Isometry3d X_GW = gcp_pose(hand, X_WL).inverse();

  std::vector<Finger> fingers;
  for (Finger& f : hand_fingers(hand))
    if (f.tip_link >= 0) fingers.push_back(std::move(f));
  if (fingers.empty())
    throw std::invalid_argument("measure_palm_width: hand '" + hand.name +
                                "' has no actor moving collision geometry");
  const Finger* thumb = nullptr;
  std::vector<const Finger*> others;
  for (const Finger& f : fingers) {
    if (f.is_thumb && !thumb)
      thumb = &f;
    else if (!f.is_thumb)
      others.push_back(&f);
  }
  if (others.empty())
    for (const Finger& f : fingers) others.push_back(&f);
  auto tip_G = [&](const Finger& f) -> Eigen::Vector3d {
    return X_GW * (X_WL[f.tip_link] * f.p_tip_L);
  };

  // Opposition direction o (docs/algorithm.md §7.1) in the GCP xy-plane; lateral axis l = z × o.
  Eigen::Vector3d o = Eigen::Vector3d::UnitX();
  if (thumb) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (const Finger* f : others) centroid += tip_G(*f);
    centroid /= static_cast<double>(others.size());
    Eigen::Vector3d d = centroid - tip_G(*thumb);
    d.z() = 0.0;
    if (d.norm() > 1e-9) o = d.normalized();
  }
  const Eigen::Vector3d lateral = Eigen::Vector3d::UnitZ().cross(o);

  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  std::vector<Eigen::Vector3d> pts;
  for (const Finger* f : others)
    for (int l : f->links) {
      pts.clear();
      append_collision_points(hand.links[l], pts);
      for (const auto& p : pts) {
        const double s = lateral.dot(X_GW * (X_WL[l] * p));
        lo = std::min(lo, s);
        hi = std::max(hi, s);
      }
    }
  return hi - lo;
}

double palm_width(const HandModel& hand) {
  return hand.palm_width_m ? *hand.palm_width_m : measure_palm_width(hand);
}

}  // namespace cordgrasp
