#include "cordgrasp/core/tighten_cord_sampled.h"

#include <algorithm>
#include <cmath>

#include "cordgrasp/core/segment_mesh_hits.h"

namespace cordgrasp {
namespace {

/// Entry–exit spreads above this are not one grazing contact.
constexpr double kMaxSpread_m = 1e-7;
/// The march stops this far before the guide's end point.
constexpr double kEndGap_m = 1e-6;

struct Guide {
  const std::vector<Eigen::Vector3d>& pts;
  std::vector<double> cum;  // arc length at each vertex
  Eigen::Vector3d at(double u) const {
    const auto it = std::upper_bound(cum.begin(), cum.end(), u);
    size_t k = size_t(std::max<long>(1, it - cum.begin())) - 1;
    k = std::min(k, pts.size() - 2);
    const double seg = cum[k + 1] - cum[k];
    const double s = seg > 0.0 ? std::clamp((u - cum[k]) / seg, 0.0, 1.0) : 0.0;
    return pts[k] + s * (pts[k + 1] - pts[k]);
  }
};

/// Hits of anchor→target that are not within `skip_a` of the anchor or `skip_b` of the target.
std::vector<SegmentHit> blocking_hits(const MeshBvh& bvh, const Eigen::Vector3d& a,
                                      const Eigen::Vector3d& b, double skip_a, double skip_b) {
  std::vector<SegmentHit> hits = segment_mesh_hits(bvh, a, b);
  const double len = (b - a).norm();
  std::vector<SegmentHit> out;
  for (const SegmentHit& h : hits)
    if (h.t * len > skip_a && (1.0 - h.t) * len > skip_b) out.push_back(h);
  return out;
}

}  // namespace

std::optional<std::vector<Eigen::Vector3d>> tighten_cord_sampled(
    const MeshBvh& bvh, const std::vector<Eigen::Vector3d>& guide,
    const SampledTightenOptions& opt) {
  if (guide.size() < 2) return guide;
  Guide g{guide, {0.0}};
  for (size_t k = 1; k < guide.size(); ++k)
    g.cum.push_back(g.cum.back() + (guide[k] - guide[k - 1]).norm());
  const double total = g.cum.back();
  const double du = std::min(opt.step_m, total / 1000.0);
  std::vector<Eigen::Vector3d> cord{guide.front()};
  Eigen::Vector3d a = guide.front();
  double skip_a = opt.self_m;  // grows to the entry–exit spread of the last grazing ray
  // The guide may end on the surface (P_l): a ray between two surface points can cross the
  // interior without any hit, so the march stops kEndGap_m before the end, where the target is
  // still outside, and appends the end point afterwards.
  const double end = std::max(0.0, total - kEndGap_m);
  double u = 0.0;
  int events = 0;
  while (u < end) {
    const double next = std::min(u + du, end);
    if (blocking_hits(bvh, a, g.at(next), skip_a, opt.self_m).empty()) {
      u = next;
      continue;
    }
    double lo = u, hi = next;
    while ((g.at(hi) - g.at(lo)).norm() >= opt.bisect_m && hi - lo > 0.0) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      if (blocking_hits(bvh, a, g.at(mid), skip_a, opt.self_m).empty())
        lo = mid;
      else
        hi = mid;
    }
    const std::vector<SegmentHit> hits = blocking_hits(bvh, a, g.at(hi), skip_a, opt.self_m);
    if (hits.empty()) {  // numerically free after all
      u = hi;
      continue;
    }
    if (++events > 100000) return std::nullopt;
    // Entry and exit of the grazing ray bracket the silhouette point.
    double spread = 0.0;
    if (hits.size() > 1) spread = (hits[1].point - hits[0].point).norm();
    if (spread > kMaxSpread_m) spread = 0.0;  // the second hit is another surface part
    a = hits.front().point;
    skip_a = std::max(opt.self_m, 2.0 * spread);
    cord.push_back(a);
    u = lo;
  }
  cord.push_back(guide.back());
  return cord;
}

}  // namespace cordgrasp
