#include "cordgrasp/core/plane_cross_section.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "prefetch.h"
#include "slice_triangle.h"

namespace cordgrasp {
namespace {

using detail::SlicePlane;

/// Conservative slack when skipping BVH boxes, far above rounding of box-vs-vertex distances.
constexpr double kBoxSlack_m = 1e-10;

/// Edge half-planes of a counter-clockwise 2D triangle: inside ⇔ n_k·x ≤ d_k for all k.
struct RegionTest {
  double nx[3], ny[3], d[3];
  explicit RegionTest(const Eigen::Vector2d* t) {
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d e = t[(k + 1) % 3] - t[k];
      const Eigen::Vector2d n = Eigen::Vector2d(e.y(), -e.x()).normalized();  // outward
      nx[k] = n.x();
      ny[k] = n.y();
      d[k] = n.dot(t[k]) + kBoxSlack_m;
    }
  }
  /// False when the disk (x, y; radius) lies entirely outside one edge line.
  bool may_meet(double x, double y, double radius) const {
    return nx[0] * x + ny[0] * y - d[0] <= radius && nx[1] * x + ny[1] * y - d[1] <= radius &&
           nx[2] * x + ny[2] * y - d[2] <= radius;
  }
};

/// Calls visit(k) for every BVH triangle k in a leaf whose box the plane may cut (and, with
/// `region`, whose bounding sphere may meet the region).
template <typename Visit>
void visit_straddling_triangles(const MeshBvh& bvh, const SlicePlane& f, const RegionTest* region,
                                Visit&& visit) {
  if (bvh.nodes.empty()) return;
  const double anx = std::abs(f.nx), any = std::abs(f.ny), anz = std::abs(f.nz);
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const int index = stack[--top];
    const MeshBvh::Node& node = bvh.nodes[index];
    const Eigen::Vector3d c = node.center(), half = node.half();
    const double radius = anx * half.x() + any * half.y() + anz * half.z();
    const double sc = f.distance(c);
    if (sc - radius > kBoxSlack_m || sc + radius < -kBoxSlack_m) continue;
    // The node's bounding sphere meets the plane inside a disk of at most its radius around
    // the projected centre.
    if (region) {
      const double x = f.ax * c.x() + f.ay * c.y() + f.az * c.z() - f.a0;
      const double y = f.bx * c.x() + f.by * c.y() + f.bz * c.z() - f.b0;
      if (!region->may_meet(x, y, node.radius)) continue;
    }
    if (node.count > 0) {
      for (int k = node.first; k < node.first + node.count; ++k) visit(k);
    } else if (top + 2 <= 128) {  // always true: median-split depth is ≤ 64
      stack[top++] = node.first;
      stack[top++] = index + 1;
      detail::prefetch(&bvh.nodes[size_t(node.first)]);  // the right child, often next but one
    }
  }
}

/// Collects segments and the (edge key, point) of their endpoints; V_S merges equal keys.
struct Collector {
  struct End {
    std::uint64_t key;
    Eigen::Vector2d p;
  };
  std::vector<Segment2> segments;
  std::vector<End> ends;
  void add(const std::vector<Eigen::Vector3d>& v, const Eigen::Vector3i& t, const SlicePlane& f) {
    Eigen::Vector2d c0, c1;
    int odd = 0;
    if (!detail::slice_triangle(v, t, f, c0, c1, &odd)) return;
    const int a = odd == 2 ? 0 : odd + 1, b = odd == 0 ? 2 : odd - 1;
    segments.push_back({c0, c1});
    ends.push_back({detail::edge_key(t[odd], t[a]), c0});
    ends.push_back({detail::edge_key(t[odd], t[b]), c1});
  }
  CrossSection finish() {
    CrossSection cs;
    cs.segments = std::move(segments);
    std::sort(ends.begin(), ends.end(), [](const End& a, const End& b) { return a.key < b.key; });
    for (size_t k = 0; k < ends.size(); ++k)
      if (k == 0 || ends[k].key != ends[k - 1].key) cs.points.push_back(ends[k].p);
    return cs;
  }
};

}  // namespace

CrossSection plane_cross_section(const Mesh& mesh, const PlaneFrame& plane) {
  const SlicePlane f(plane);
  Collector c;
  for (const Eigen::Vector3i& t : mesh.triangles) c.add(mesh.vertices, t, f);
  return c.finish();
}

CrossSection plane_cross_section(const MeshBvh& bvh, const PlaneFrame& plane) {
  const SlicePlane f(plane);
  Collector c;
  visit_straddling_triangles(bvh, f, nullptr,
                             [&](int k) { c.add(bvh.vertices, bvh.triangles[k], f); });
  return c.finish();
}

void append_plane_cross_section_segments(const MeshBvh& bvh, const PlaneFrame& plane,
                                         std::vector<Segment2>& segments,
                                         const Eigen::Vector2d* region) {
  const SlicePlane f(plane);
  Eigen::Vector2d c0, c1;
  auto visit = [&](int k) {
    if (detail::slice_triangle(bvh.vertices, bvh.triangles[k], f, c0, c1))
      segments.push_back({c0, c1});
  };
  if (region) {
    const RegionTest test(region);
    visit_straddling_triangles(bvh, f, &test, visit);
  } else {
    visit_straddling_triangles(bvh, f, nullptr, visit);
  }
}

}  // namespace cordgrasp
