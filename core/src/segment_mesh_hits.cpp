#include "cordgrasp/core/segment_mesh_hits.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cordgrasp {
namespace {

/// Two-sided Möller–Trumbore; returns t ∈ [0, 1] or a negative value for a miss.
inline double intersect(const Eigen::Vector3d& o, const Eigen::Vector3d& d,
                        const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                        const Eigen::Vector3d& c) {
  const Eigen::Vector3d e1 = b - a, e2 = c - a;
  const Eigen::Vector3d p = d.cross(e2);
  const double det = e1.dot(p);
  if (det == 0.0) return -1.0;  // segment parallel to the triangle plane: grazing, no hit
  const double inv = 1.0 / det;
  const Eigen::Vector3d s = o - a;
  const double u = s.dot(p) * inv;
  if (u < 0.0 || u > 1.0) return -1.0;
  const Eigen::Vector3d q = s.cross(e1);
  const double v = d.dot(q) * inv;
  if (v < 0.0 || u + v > 1.0) return -1.0;
  const double t = e2.dot(q) * inv;
  return (t >= 0.0 && t <= 1.0) ? t : -1.0;
}

std::vector<SegmentHit> finish(std::vector<SegmentHit>& hits, const Eigen::Vector3d& p0,
                               const Eigen::Vector3d& p1, const SegmentHitOptions& opt) {
  const double len = (p1 - p0).norm();
  std::sort(hits.begin(), hits.end(), [](const SegmentHit& a, const SegmentHit& b) {
    return a.t < b.t || (a.t == b.t && a.triangle < b.triangle);
  });
  std::vector<SegmentHit> out;
  for (const SegmentHit& h : hits) {
    if (h.t * len <= opt.ignore_near_p0_m && opt.ignore_near_p0_m > 0.0) continue;
    if (!out.empty() && (h.t - out.back().t) * len < opt.merge_m) continue;
    out.push_back(h);
  }
  return out;
}

}  // namespace

std::vector<SegmentHit> segment_mesh_hits(const Mesh& mesh, const Eigen::Vector3d& p0,
                                          const Eigen::Vector3d& p1,
                                          const SegmentHitOptions& options) {
  std::vector<SegmentHit> hits;
  const Eigen::Vector3d d = p1 - p0;
  for (int k = 0; k < int(mesh.triangles.size()); ++k) {
    const Eigen::Vector3i& t = mesh.triangles[k];
    const double s =
        intersect(p0, d, mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
    if (s >= 0.0) hits.push_back({s, p0 + s * d, k});
  }
  return finish(hits, p0, p1, options);
}

namespace {

/// Visits BVH leaf triangles whose (padded) box the segment crosses; stops when visit → true.
template <typename Visit>
void visit_segment_triangles(const MeshBvh& bvh, const Eigen::Vector3d& p0,
                             const Eigen::Vector3d& d, Visit&& visit) {
  if (bvh.nodes.empty()) return;
  Eigen::Vector3d inv_d;
  for (int c = 0; c < 3; ++c)
    inv_d[c] = d[c] != 0.0 ? 1.0 / d[c] : std::numeric_limits<double>::infinity();
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const int index = stack[--top];
    const MeshBvh::Node& node = bvh.nodes[index];
    // Slab test of the segment's t ∈ [0, 1] against the (slightly padded) box.
    double t0 = 0.0, t1 = 1.0;
    bool miss = false;
    for (int c = 0; c < 3 && !miss; ++c) {
      const double pad = 1e-12 * (1.0 + std::abs(node.lo[c]) + std::abs(node.hi[c]));
      const double lo = node.lo[c] - pad, hi = node.hi[c] + pad;
      if (d[c] == 0.0) {
        miss = p0[c] < lo || p0[c] > hi;
        continue;
      }
      double ta = (lo - p0[c]) * inv_d[c], tb = (hi - p0[c]) * inv_d[c];
      if (ta > tb) std::swap(ta, tb);
      t0 = std::max(t0, ta);
      t1 = std::min(t1, tb);
      miss = t0 > t1;
    }
    if (miss) continue;
    if (node.count > 0) {
      for (int k = node.first; k < node.first + node.count; ++k)
        if (visit(k)) return;
    } else if (top + 2 <= 128) {  // always true: median-split depth is ≤ 64
      stack[top++] = node.first;
      stack[top++] = index + 1;
    }
  }
}

}  // namespace

std::vector<SegmentHit> segment_mesh_hits(const MeshBvh& bvh, const Eigen::Vector3d& p0,
                                          const Eigen::Vector3d& p1,
                                          const SegmentHitOptions& options) {
  std::vector<SegmentHit> hits;
  const Eigen::Vector3d d = p1 - p0;
  visit_segment_triangles(bvh, p0, d, [&](int k) {
    const Eigen::Vector3i& t = bvh.triangles[k];
    const double s = intersect(p0, d, bvh.vertices[t[0]], bvh.vertices[t[1]], bvh.vertices[t[2]]);
    if (s >= 0.0) hits.push_back({s, p0 + s * d, bvh.triangle_ids[k]});
    return false;
  });
  return finish(hits, p0, p1, options);
}

bool segment_meets_mesh(const MeshBvh& bvh, const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                        double margin_m) {
  const Eigen::Vector3d d = p1 - p0;
  const double len = d.norm();
  if (len <= 2.0 * margin_m) return false;
  const double t_lo = margin_m / len, t_hi = 1.0 - margin_m / len;
  bool hit = false;
  visit_segment_triangles(bvh, p0, d, [&](int k) {
    const Eigen::Vector3i& t = bvh.triangles[k];
    const double s = intersect(p0, d, bvh.vertices[t[0]], bvh.vertices[t[1]], bvh.vertices[t[2]]);
    hit = s > t_lo && s < t_hi;
    return hit;
  });
  return hit;
}

}  // namespace cordgrasp
