#include "cordgrasp/core/mesh_bvh.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "huge_pages.h"

namespace cordgrasp {
namespace {

/// A triangle being placed: its split key and its index in the triangle list. The key sits
/// beside the index so that a split reads keys in sequence, not through an index.
struct Item {
  Eigen::Vector3d key;  ///< kCornerSum: corner sum; kCentroidThenIndex: centroid
  int id = 0;
};

struct Builder {
  const std::vector<Eigen::Vector3d>& vertices;
  const std::vector<Eigen::Vector3i>& triangles;
  int max_leaf;
  MeshBvhSplit split;
  std::vector<Item> items;
  MeshBvh& bvh;

  void bounds(int begin, int end, Eigen::Vector3d& lo, Eigen::Vector3d& hi) const {
    lo.setConstant(std::numeric_limits<double>::infinity());
    hi = -lo;
    for (int k = begin; k < end; ++k) {
      const Eigen::Vector3i& t = triangles[size_t(items[size_t(k)].id)];
      for (int c = 0; c < 3; ++c) {
        lo = lo.cwiseMin(vertices[size_t(t[c])]);
        hi = hi.cwiseMax(vertices[size_t(t[c])]);
      }
    }
  }

  /// Centre, half size and bounding-sphere radius from the box (stored: the queries' hot path).
  static void set_sphere(MeshBvh::Node& node) {
    node.center = 0.5 * (node.lo + node.hi);
    node.half = 0.5 * (node.hi - node.lo);
    node.radius = node.half.norm();
  }

  /// Builds the subtree of items[begin, end); a node's box is its triangles' corners (leaf) or
  /// the union of its children's boxes (the same box, in linear total time).
  int build(int begin, int end) {
    const int index = int(bvh.nodes.size());
    bvh.nodes.emplace_back();
    if (end - begin <= max_leaf) {
      Eigen::Vector3d lo, hi;
      bounds(begin, end, lo, hi);
      bvh.nodes[index].lo = lo;
      bvh.nodes[index].hi = hi;
      set_sphere(bvh.nodes[index]);
      bvh.nodes[index].first = begin;
      bvh.nodes[index].count = end - begin;
      return index;
    }
    Eigen::Vector3d klo = items[size_t(begin)].key, khi = klo;
    for (int k = begin + 1; k < end; ++k) {
      klo = klo.cwiseMin(items[size_t(k)].key);
      khi = khi.cwiseMax(items[size_t(k)].key);
    }
    // Centroid bounds: for kCornerSum the centroid is sum·(1/3), and rounding a product is
    // monotone, so the bounds of the centroids are the key bounds times 1/3, exactly.
    const Eigen::Vector3d clo =
        split == MeshBvhSplit::kCornerSum ? Eigen::Vector3d(klo * (1.0 / 3.0)) : klo;
    const Eigen::Vector3d chi =
        split == MeshBvhSplit::kCornerSum ? Eigen::Vector3d(khi * (1.0 / 3.0)) : khi;
    int axis = 0;
    (chi - clo).maxCoeff(&axis);
    const int mid = begin + (end - begin) / 2;
    const auto first = items.begin() + begin;
    if (split == MeshBvhSplit::kCornerSum)
      std::nth_element(first, items.begin() + mid, items.begin() + end,
                       [axis](const Item& a, const Item& b) { return a.key[axis] < b.key[axis]; });
    else
      std::nth_element(first, items.begin() + mid, items.begin() + end,
                       [axis](const Item& a, const Item& b) {
                         const double ca = a.key[axis], cb = b.key[axis];
                         return ca < cb || (ca == cb && a.id < b.id);
                       });
    build(begin, mid);
    const int right = build(mid, end);
    MeshBvh::Node& node = bvh.nodes[index];
    node.lo = bvh.nodes[index + 1].lo.cwiseMin(bvh.nodes[right].lo);
    node.hi = bvh.nodes[index + 1].hi.cwiseMax(bvh.nodes[right].hi);
    set_sphere(node);
    node.first = right;
    node.count = 0;
    return index;
  }
};

/// The BVH of `triangles` over `vertices` (bvh.vertices is set by the caller).
void build_bvh_nodes(const std::vector<Eigen::Vector3d>& vertices,
                     const std::vector<Eigen::Vector3i>& triangles, int max_leaf_triangles,
                     MeshBvhSplit split, MeshBvh& bvh) {
  const int n = int(triangles.size());
  if (n == 0) return;
  Builder b{vertices, triangles, max_leaf_triangles, split, {}, bvh};
  detail::reserve_huge(b.items, size_t(n));
  b.items.resize(size_t(n));
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector3i& t = triangles[size_t(k)];
    const Eigen::Vector3d sum =
        vertices[size_t(t[0])] + vertices[size_t(t[1])] + vertices[size_t(t[2])];
    b.items[size_t(k)].key = split == MeshBvhSplit::kCornerSum ? sum : Eigen::Vector3d(sum / 3.0);
    b.items[size_t(k)].id = k;
  }
  // Median splits leave at least ⌈max_leaf / 2⌉ triangles in a leaf (fewer only for a mesh
  // that small): at most 2·leaves − 1 nodes, reserved at once (no regrowth copy).
  const int min_leaf = std::max(1, (max_leaf_triangles + 1) / 2);
  detail::reserve_huge(bvh.nodes, size_t(2 * (n / min_leaf + 1)));
  b.build(0, n);
  detail::reserve_huge(bvh.triangle_ids, size_t(n));
  detail::reserve_huge(bvh.triangles, size_t(n));
  bvh.triangle_ids.resize(size_t(n));
  bvh.triangles.resize(size_t(n));
  for (int k = 0; k < n; ++k) {
    const int id = b.items[size_t(k)].id;
    bvh.triangle_ids[size_t(k)] = id;
    bvh.triangles[size_t(k)] = triangles[size_t(id)];
  }
}

}  // namespace

MeshBvh build_mesh_bvh(const Mesh& mesh, int max_leaf_triangles, MeshBvhSplit split) {
  if (max_leaf_triangles < 1) throw std::invalid_argument("build_mesh_bvh: max_leaf_triangles < 1");
  MeshBvh bvh;
  bvh.vertices = mesh.vertices;
  build_bvh_nodes(mesh.vertices, mesh.triangles, max_leaf_triangles, split, bvh);
  return bvh;
}

MeshBvh build_object_bvh(const Mesh& mesh) {
  std::vector<Eigen::Vector3i> usable;  // triangles of non-zero area
  detail::reserve_huge(usable, mesh.triangles.size());
  std::vector<int> ids;  // usable triangle -> mesh triangle
  detail::reserve_huge(ids, mesh.triangles.size());
  for (size_t k = 0; k < mesh.triangles.size(); ++k) {
    const Eigen::Vector3i& t = mesh.triangles[k];
    const Eigen::Vector3d& a = mesh.vertices[static_cast<size_t>(t[0])];
    const Eigen::Vector3d& b = mesh.vertices[static_cast<size_t>(t[1])];
    const Eigen::Vector3d& c = mesh.vertices[static_cast<size_t>(t[2])];
    if ((b - a).cross(c - a).squaredNorm() <= 0.0) continue;
    usable.push_back(t);
    ids.push_back(static_cast<int>(k));
  }
  const int leaf =
      static_cast<int>(usable.size()) > kLargeMeshTriangles ? kLargeMeshLeafTriangles : 4;
  MeshBvh bvh;
  detail::reserve_huge(bvh.vertices, mesh.vertices.size());
  bvh.vertices.assign(mesh.vertices.begin(), mesh.vertices.end());
  build_bvh_nodes(mesh.vertices, usable, leaf, MeshBvhSplit::kCornerSum, bvh);
  for (int& id : bvh.triangle_ids) id = ids[static_cast<size_t>(id)];
  return bvh;
}

}  // namespace cordgrasp
