#include "cordgrasp/core/mesh_bvh.h"

#include <algorithm>
#include <atomic>
#include <limits>
#include <stdexcept>

#include "cordgrasp/core/parallel_for.h"
#include "huge_pages.h"

namespace cordgrasp {
namespace {

/// A triangle being placed: its split key and its index in the triangle list. The key sits
/// beside the index so that a split reads keys in sequence, not through an index.
struct Item {
  Eigen::Vector3d key;  ///< kCornerSum: corner sum; kCentroidThenIndex: centroid
  int id = 0;
};

/// Triangles above which the BVH of a large mesh is built on two threads: the root's two
/// subtrees at once, and its per-triangle passes in two halves.
constexpr int kParallelBuildTriangles = 100000;

/// Calls fn(begin, end) over [0, n): in two halves on two threads when `threads` > 1 and n is
/// large, else once on this thread.
template <typename F>
void in_halves(int n, int threads, F&& fn) {
  if (threads > 1 && n > kParallelBuildTriangles)
    parallel_for(2, 2, [&](int half) { half == 0 ? fn(0, n / 2) : fn(n / 2, n); });
  else
    fn(0, n);
}

struct Builder {
  const std::vector<Eigen::Vector3d>& vertices;
  const std::vector<Eigen::Vector3i>& triangles;
  int max_leaf;
  MeshBvhSplit split;
  std::vector<Item>& items;
  MeshBvh::Node* nodes;  ///< the whole tree's nodes, sized beforehand
  int next = 0;          ///< index of the next node this builder makes (preorder)

  MeshBvh::Node& node(int index) { return nodes[index]; }

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

  /// The bounding-sphere radius from the box (stored: the region test's hot path).
  static void set_sphere(MeshBvh::Node& node) { node.radius = node.half().norm(); }

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
    const int index = next++;
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
  in_halves(n, threads, [&](int begin, int end) {
    for (int k = begin; k < end; ++k) {
      const Eigen::Vector3i& t = triangles[size_t(k)];
      const Eigen::Vector3d sum =
          vertices[size_t(t[0])] + vertices[size_t(t[1])] + vertices[size_t(t[2])];
      items[size_t(k)].key = split == MeshBvhSplit::kCornerSum ? sum : Eigen::Vector3d(sum / 3.0);
      items[size_t(k)].id = k;
    }
  });
  // The node count is known from n alone (median splits): sized at once, each subtree's
  // builder writes its own index range.
  const size_t node_count = size_t(subtree_nodes(n, max_leaf_triangles));
  detail::reserve_huge(bvh.nodes, node_count);
  bvh.nodes.resize(node_count);
  Builder root{vertices, triangles, max_leaf_triangles, split, items, bvh.nodes.data()};
  if (threads > 1 && n > kParallelBuildTriangles) {
    const int mid = root.split_at_median(0, n);
    const int right_index = 1 + subtree_nodes(mid, max_leaf_triangles);
    Builder left{vertices, triangles, max_leaf_triangles, split, items, bvh.nodes.data(), 1};
    Builder right{vertices, triangles,        max_leaf_triangles, split,
                  items,    bvh.nodes.data(), right_index};
    // The first exception (e.g. out of memory) is rethrown here after both halves end.
    parallel_for(2, 2, [&](int half) { half == 0 ? left.build(0, mid) : right.build(mid, n); });
    Builder::join(bvh.nodes[0], bvh.nodes[1], bvh.nodes[size_t(right_index)], right_index);
  } else {
    root.build(0, n);
  }
  detail::reserve_huge(bvh.triangle_ids, size_t(n));
  detail::reserve_huge(bvh.triangles, size_t(n));
  bvh.triangle_ids.resize(size_t(n));
  bvh.triangles.resize(size_t(n));
  in_halves(n, threads, [&](int begin, int end) {
    for (int k = begin; k < end; ++k) {
      const int id = items[size_t(k)].id;
      bvh.triangle_ids[size_t(k)] = id;
      bvh.triangles[size_t(k)] = triangles[size_t(id)];
    }
  });
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
  const int nt = static_cast<int>(mesh.triangles.size());
  std::vector<char> has_area(static_cast<size_t>(nt));
  std::atomic<int> without_area{0};
  in_halves(nt, threads, [&](int begin, int end) {
    int zero = 0;
    for (int k = begin; k < end; ++k) {
      const Eigen::Vector3i& t = mesh.triangles[static_cast<size_t>(k)];
      const Eigen::Vector3d& a = mesh.vertices[static_cast<size_t>(t[0])];
      const Eigen::Vector3d& b = mesh.vertices[static_cast<size_t>(t[1])];
      const Eigen::Vector3d& c = mesh.vertices[static_cast<size_t>(t[2])];
      const bool area = !((b - a).cross(c - a).squaredNorm() <= 0.0);  // NaN: kept, as before
      has_area[static_cast<size_t>(k)] = area;
      zero += area ? 0 : 1;
    }
    without_area += zero;
  });
  // Usually every triangle has an area (load_mesh drops those without): then the mesh's own
  // list is used, not a copy.
  std::vector<Eigen::Vector3i> usable;  // triangles of non-zero area, when some have none
  std::vector<int> ids;                 // usable triangle -> mesh triangle
  if (without_area > 0) {
    detail::reserve_huge(usable, static_cast<size_t>(nt - without_area));
    detail::reserve_huge(ids, static_cast<size_t>(nt - without_area));
    for (int k = 0; k < nt; ++k)
      if (has_area[static_cast<size_t>(k)]) {
        usable.push_back(mesh.triangles[static_cast<size_t>(k)]);
        ids.push_back(k);
      }
  }
  const std::vector<Eigen::Vector3i>& triangles = without_area > 0 ? usable : mesh.triangles;
  const int leaf =
      static_cast<int>(triangles.size()) > kLargeMeshTriangles ? kLargeMeshLeafTriangles : 4;
  MeshBvh bvh;
  build_bvh_nodes(mesh.vertices, triangles, leaf, MeshBvhSplit::kCornerSum, bvh, threads);
  if (without_area > 0)
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
