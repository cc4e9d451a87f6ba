#include "cordgrasp/core/plane_cross_section.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace cordgrasp {
namespace {

/// Conservative slack when skipping BVH boxes, far above rounding of box-vs-vertex distances.
constexpr double kBoxSlack_m = 1e-10;

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

/// Edge half-planes of a counter-clockwise 2D triangle: inside ⇔ n_k·x ≤ d_k for all k.
struct RegionTest {
  Eigen::Vector2d n[3];
  double d[3];
  explicit RegionTest(const Eigen::Vector2d* t) {
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d e = t[(k + 1) % 3] - t[k];
      n[k] = Eigen::Vector2d(e.y(), -e.x()).normalized();  // outward for CCW
      d[k] = n[k].dot(t[k]);
    }
  }
  /// False when the disk (c, radius) lies entirely outside one edge line.
  bool may_meet(const Eigen::Vector2d& c, double radius) const {
    for (int k = 0; k < 3; ++k)
      if (n[k].dot(c) - d[k] > radius + kBoxSlack_m) return false;
    return true;
  }
};

template <typename Visit>
void visit_straddling_triangles(const MeshBvh& bvh, const PlaneFrame& f,
                                const RegionTest* region, Visit&& visit) {
  if (bvh.nodes.empty()) return;
  const Eigen::Vector3d abs_n = f.normal.cwiseAbs();
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const int index = stack[--top];
    const MeshBvh::Node& node = bvh.nodes[index];
    const double radius = abs_n.dot(node.half);
    const double sc = signed_distance(node.center, f);
    if (sc - radius > kBoxSlack_m || sc + radius < -kBoxSlack_m) continue;
    if (region) {
      // The node's bounding sphere cuts the plane in a disk around the projected centre.
      const double r2 = node.half.squaredNorm() - sc * sc;
      if (!region->may_meet(f.to_2d(node.center), std::sqrt(std::max(0.0, r2)))) continue;
    }
    if (node.count > 0) {
      for (int k = node.first; k < node.first + node.count; ++k) visit(k);
    } else if (top + 2 <= 128) {  // always true: median-split depth is ≤ 64
      stack[top++] = node.first;
      stack[top++] = index + 1;
    }
  }
}

CrossSection finish(std::vector<Crossing>& ends, std::vector<Segment2>&& segments) {
  CrossSection cs;
  cs.segments = std::move(segments);
  std::sort(ends.begin(), ends.end(),
            [](const Crossing& a, const Crossing& b) { return a.edge_key < b.edge_key; });
  for (size_t k = 0; k < ends.size(); ++k)
    if (k == 0 || ends[k].edge_key != ends[k - 1].edge_key) cs.points.push_back(ends[k].p);
  return cs;
}

}  // namespace

CrossSection plane_cross_section(const Mesh& mesh, const PlaneFrame& plane) {
  std::vector<Crossing> ends;
  std::vector<Segment2> segments;
  Crossing c0, c1;
  for (const Eigen::Vector3i& t : mesh.triangles)
    if (slice_triangle(mesh.vertices, t, plane, c0, c1)) {
      segments.push_back({c0.p, c1.p});
      ends.push_back(c0);
      ends.push_back(c1);
    }
  return finish(ends, std::move(segments));
}

CrossSection plane_cross_section(const MeshBvh& bvh, const PlaneFrame& plane) {
  std::vector<Crossing> ends;
  std::vector<Segment2> segments;
  Crossing c0, c1;
  visit_straddling_triangles(bvh, plane, nullptr, [&](int k) {
    if (slice_triangle(bvh.vertices, bvh.triangles[k], plane, c0, c1)) {
      segments.push_back({c0.p, c1.p});
      ends.push_back(c0);
      ends.push_back(c1);
    }
  });
  return finish(ends, std::move(segments));
}

void append_plane_cross_section_segments(const MeshBvh& bvh, const PlaneFrame& plane,
                                         std::vector<Segment2>& segments,
                                         const Eigen::Vector2d* region) {
  Crossing c0, c1;
  const std::optional<RegionTest> test =
      region ? std::optional<RegionTest>(RegionTest(region)) : std::nullopt;
  visit_straddling_triangles(bvh, plane, test ? &*test : nullptr, [&](int k) {
    if (slice_triangle(bvh.vertices, bvh.triangles[k], plane, c0, c1))
      segments.push_back({c0.p, c1.p});
  });
}

}  // namespace cordgrasp
