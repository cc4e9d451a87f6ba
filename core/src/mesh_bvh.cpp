#include "cordgrasp/core/mesh_bvh.h"

#include <algorithm>
#include <exception>
#include <limits>
#include <stdexcept>
#include <thread>

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
  std::vector<Item>& items;
  std::vector<MeshBvh::Node>& nodes;  ///< this builder's subtree, from node index `base`
  int base = 0;

  MeshBvh::Node& node(int index) { return nodes[size_t(index - base)]; }

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

  /// Orders items[begin, end) about their median along the longest centroid axis; returns the
  /// median's position, where the right child begins.
  int split_at_median(int begin, int end) {
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
    return mid;
  }

  /// An inner node's box: the union of its children's boxes (the same box as its triangles').
  static void join(MeshBvh::Node& inner, const MeshBvh::Node& left, const MeshBvh::Node& right,
                   int right_index) {
    inner.lo = left.lo.cwiseMin(right.lo);
    inner.hi = left.hi.cwiseMax(right.hi);
    set_sphere(inner);
    inner.first = right_index;
    inner.count = 0;
  }

  /// Builds the subtree of items[begin, end) in preorder (left child = own index + 1).
  int build(int begin, int end) {
    const int index = base + int(nodes.size());
    nodes.emplace_back();
    if (end - begin <= max_leaf) {
      Eigen::Vector3d lo, hi;
      bounds(begin, end, lo, hi);
      MeshBvh::Node& leaf = node(index);
      leaf.lo = lo;
      leaf.hi = hi;
      set_sphere(leaf);
      leaf.first = begin;
      leaf.count = end - begin;
      return index;
    }
    const int mid = split_at_median(begin, end);
    build(begin, mid);
    const int right = build(mid, end);
    join(node(index), node(index + 1), node(right), right);
    return index;
  }
};

/// Nodes of the subtree of `n` triangles that Builder::build makes.
int subtree_nodes(int n, int max_leaf) {
  return n <= max_leaf ? 1
                       : 1 + subtree_nodes(n / 2, max_leaf) + subtree_nodes(n - n / 2, max_leaf);
}

/// Triangles above which build_bvh_nodes builds the root's two subtrees on two threads.
constexpr int kParallelBuildTriangles = 100000;

/// The BVH of `triangles` over `vertices` (bvh.vertices is set by the caller). With threads > 1
/// a large set's two halves are built at once: the same nodes, in the same order.
void build_bvh_nodes(const std::vector<Eigen::Vector3d>& vertices,
                     const std::vector<Eigen::Vector3i>& triangles, int max_leaf_triangles,
                     MeshBvhSplit split, MeshBvh& bvh, int threads) {
  const int n = int(triangles.size());
  if (n == 0) return;
  std::vector<Item> items;
  detail::reserve_huge(items, size_t(n));
  items.resize(size_t(n));
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector3i& t = triangles[size_t(k)];
    const Eigen::Vector3d sum =
        vertices[size_t(t[0])] + vertices[size_t(t[1])] + vertices[size_t(t[2])];
    items[size_t(k)].key = split == MeshBvhSplit::kCornerSum ? sum : Eigen::Vector3d(sum / 3.0);
    items[size_t(k)].id = k;
  }
  // Median splits leave at least ⌈max_leaf / 2⌉ triangles in a leaf (fewer only for a mesh
  // that small): at most 2·leaves − 1 nodes, reserved at once (no regrowth copy).
  const int min_leaf = std::max(1, (max_leaf_triangles + 1) / 2);
  detail::reserve_huge(bvh.nodes, size_t(2 * (n / min_leaf + 1)));
  Builder root{vertices, triangles, max_leaf_triangles, split, items, bvh.nodes};
  if (threads > 1 && n > kParallelBuildTriangles) {
    bvh.nodes.emplace_back();
    const int mid = root.split_at_median(0, n);
    const int right_index = 1 + subtree_nodes(mid, max_leaf_triangles);
    std::vector<MeshBvh::Node> right_nodes;
    detail::reserve_huge(right_nodes, size_t(2 * ((n - mid) / min_leaf + 1)));
    Builder left{vertices, triangles, max_leaf_triangles, split, items, bvh.nodes, 0};
    Builder right{vertices, triangles, max_leaf_triangles, split, items, right_nodes, right_index};
    std::exception_ptr failed;  // e.g. out of memory: thrown here, not std::terminate
    std::thread worker([&]() {  // items[mid, n) only
      try {
        right.build(mid, n);
      } catch (...) {
        failed = std::current_exception();
      }
    });
    try {
      left.build(0, mid);
    } catch (...) {
      worker.join();
      throw;
    }
    worker.join();
    if (failed) std::rethrow_exception(failed);
    bvh.nodes.insert(bvh.nodes.end(), right_nodes.begin(), right_nodes.end());
    Builder::join(bvh.nodes[0], bvh.nodes[1], bvh.nodes[size_t(right_index)], right_index);
  } else {
    root.build(0, n);
  }
  detail::reserve_huge(bvh.triangle_ids, size_t(n));
  detail::reserve_huge(bvh.triangles, size_t(n));
  bvh.triangle_ids.resize(size_t(n));
  bvh.triangles.resize(size_t(n));
  for (int k = 0; k < n; ++k) {
    const int id = items[size_t(k)].id;
    bvh.triangle_ids[size_t(k)] = id;
    bvh.triangles[size_t(k)] = triangles[size_t(id)];
  }
}

}  // namespace

MeshBvh build_mesh_bvh(const Mesh& mesh, int max_leaf_triangles, MeshBvhSplit split) {
  if (max_leaf_triangles < 1) throw std::invalid_argument("build_mesh_bvh: max_leaf_triangles < 1");
  MeshBvh bvh;
  bvh.vertices = mesh.vertices;
  build_bvh_nodes(mesh.vertices, mesh.triangles, max_leaf_triangles, split, bvh, 1);
  return bvh;
}

MeshBvh build_object_bvh(const Mesh& mesh, int threads) {
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
  build_bvh_nodes(mesh.vertices, usable, leaf, MeshBvhSplit::kCornerSum, bvh, threads);
  for (int& id : bvh.triangle_ids) id = ids[static_cast<size_t>(id)];
  if (leaf == kLargeMeshLeafTriangles) {
    // A scan's vertices renumbered in first use along the leaves: a plane or segment query then
    // reads neighbouring memory, whatever order the file listed its vertices in.
    std::vector<int> remap;
    detail::assign_huge(remap, mesh.vertices.size(), -1);
    detail::reserve_huge(bvh.vertices, mesh.vertices.size());
    for (Eigen::Vector3i& t : bvh.triangles)
      for (int k = 0; k < 3; ++k) {
        int& r = remap[static_cast<size_t>(t[k])];
        if (r < 0) {
          r = static_cast<int>(bvh.vertices.size());
          bvh.vertices.push_back(mesh.vertices[static_cast<size_t>(t[k])]);
        }
        t[k] = r;
      }
  } else {
    bvh.vertices = mesh.vertices;
  }
  return bvh;
}

}  // namespace cordgrasp
