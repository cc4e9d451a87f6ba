#pragma once
// Private: slicing one soup triangle with a plane (spec §2.2), shared by the slicers.
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

inline double signed_distance(const Eigen::Vector3d& x, const PlaneFrame& f) {
  return f.normal.dot(x - f.origin);
}

/// Crossing of edge (i, j) with the plane, computed from the lower vertex index.
inline Crossing edge_crossing(const std::vector<Eigen::Vector3d>& v, int i, int j, double si,
                              double sj, const PlaneFrame& f) {
  if (j < i) {
    std::swap(i, j);
    std::swap(si, sj);
  }
  const Eigen::Vector3d x = v[i] + (v[j] - v[i]) * (si / (si - sj));
  return {f.to_2d(x), (std::uint64_t(std::uint32_t(i)) << 32) | std::uint32_t(j)};
}

/// Slices one triangle; returns false unless its vertex signs are mixed.
inline bool slice_triangle(const std::vector<Eigen::Vector3d>& v, const Eigen::Vector3i& t,
                           const PlaneFrame& f, Crossing& c0, Crossing& c1) {
  const double s[3] = {signed_distance(v[t[0]], f), signed_distance(v[t[1]], f),
                       signed_distance(v[t[2]], f)};
  const bool pos[3] = {s[0] > 0.0, s[1] > 0.0, s[2] > 0.0};
  if (pos[0] == pos[1] && pos[1] == pos[2]) return false;
  // The odd vertex (sign differs from both others) owns the two mixed edges.
  const int odd = (pos[0] != pos[1] && pos[0] != pos[2]) ? 0 : (pos[1] != pos[0] ? 1 : 2);
  const int a = (odd + 1) % 3, b = (odd + 2) % 3;
  c0 = edge_crossing(v, t[odd], t[a], s[odd], s[a], f);
  c1 = edge_crossing(v, t[odd], t[b], s[odd], s[b], f);
  return true;
}

}  // namespace cordgrasp::detail
