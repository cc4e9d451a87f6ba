#include "cordgrasp/core/plane_cross_section.h"

#include "slice_triangle.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace cordgrasp {
namespace {

using detail::Crossing;
using detail::signed_distance;
using detail::slice_triangle;

/// Conservative slack when skipping BVH boxes, far above rounding of box-vs-vertex distances.
constexpr double kBoxSlack_m = 1e-10;

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
    // The node's bounding sphere meets the plane inside a disk of at most its radius around
    // the projected centre.
    if (region && !region->may_meet(f.to_2d(node.center), node.radius)) continue;
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
