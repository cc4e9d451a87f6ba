#pragma once
// Private: slicing one soup triangle with a plane (docs/algorithm.md §2.1), shared by the slicers.
#include <Eigen/Core>
#include <cstdint>
#include <utility>
#include <vector>

#include "cordgrasp/core/guide_frame.h"

namespace cordgrasp::detail {

struct Crossing {
  Eigen::Vector2d p;
  std::uint64_t edge_key;
};

/// Plane constants of the slicer: s(X) = ν·X − ν·O, 2D = (e1·X − e1·O, e2·X − e2·O).
struct SlicePlane {
  double nx, ny, nz, n0;
  double ax, ay, az, a0;  // e1
  double bx, by, bz, b0;  // e2
  explicit SlicePlane(const PlaneFrame& f)
      : nx(f.normal.x()),
        ny(f.normal.y()),
        nz(f.normal.z()),
        n0(f.normal.dot(f.origin)),
        ax(f.e1.x()),
        ay(f.e1.y()),
        az(f.e1.z()),
        a0(f.e1.dot(f.origin)),
        bx(f.e2.x()),
        by(f.e2.y()),
        bz(f.e2.z()),
        b0(f.e2.dot(f.origin)) {}
  double distance(const Eigen::Vector3d& x) const {
    return nx * x.x() + ny * x.y() + nz * x.z() - n0;
  }
};

/// Signed distance s = ν·(X − O) as the slicer computes it [m].
inline double signed_distance(const Eigen::Vector3d& x, const SlicePlane& f) {
  return f.distance(x);
}

/// Crossing of edge (i, j) with the plane, computed from the lower vertex index so both
/// triangles sharing the edge get bit-identical points.
inline Eigen::Vector2d edge_crossing(const std::vector<Eigen::Vector3d>& v, int i, int j, double si,
                                     double sj, const SlicePlane& f) {
  if (j < i) {
    std::swap(i, j);
    std::swap(si, sj);
  }
  const double t = si / (si - sj);
  const Eigen::Vector3d& a = v[i];
  const Eigen::Vector3d& b = v[j];
  const double x = a.x() + (b.x() - a.x()) * t;
  const double y = a.y() + (b.y() - a.y()) * t;
  const double z = a.z() + (b.z() - a.z()) * t;
  return {f.ax * x + f.ay * y + f.az * z - f.a0, f.bx * x + f.by * y + f.bz * z - f.b0};
}

inline std::uint64_t edge_key(int i, int j) {
  if (j < i) std::swap(i, j);
  return (std::uint64_t(std::uint32_t(i)) << 32) | std::uint32_t(j);
}

/// Slices one triangle; returns false unless its vertex signs are mixed ("+" iff s > 0).
/// On success the segment runs c0 → c1; `odd`, `a`, `b` name the local vertices so callers
/// can form edge keys (odd, a) and (odd, b).
inline bool slice_triangle(const std::vector<Eigen::Vector3d>& v, const Eigen::Vector3i& t,
                           const SlicePlane& f, Eigen::Vector2d& c0, Eigen::Vector2d& c1,
                           int* odd_out = nullptr) {
  const double s0 = f.distance(v[t[0]]), s1 = f.distance(v[t[1]]), s2 = f.distance(v[t[2]]);
  const bool p0 = s0 > 0.0, p1 = s1 > 0.0, p2 = s2 > 0.0;
  if (p0 == p1 && p1 == p2) return false;
  // The odd vertex (sign differs from both others) owns the two mixed edges.
  const int odd = (p0 != p1 && p0 != p2) ? 0 : (p1 != p0 ? 1 : 2);
  const double s[3] = {s0, s1, s2};
  const int a = odd == 2 ? 0 : odd + 1, b = odd == 0 ? 2 : odd - 1;
  c0 = edge_crossing(v, t[odd], t[a], s[odd], s[a], f);
  c1 = edge_crossing(v, t[odd], t[b], s[odd], s[b], f);
  if (odd_out) *odd_out = odd;
  return true;
}

}  // namespace cordgrasp::detail
