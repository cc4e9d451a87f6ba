#include "cordgrasp/core/mesh_bvh.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace cordgrasp {
namespace {

struct Builder {
  const Mesh& mesh;
  int max_leaf;
  MeshBvhSplit split;
  std::vector<Eigen::Vector3d> centroid;
  std::vector<Eigen::Vector3d> corner_sum;  // kCornerSum only
  std::vector<int> order;
  MeshBvh& bvh;

  void bounds(int begin, int end, Eigen::Vector3d& lo, Eigen::Vector3d& hi) const {
    lo.setConstant(std::numeric_limits<double>::infinity());
    hi = -lo;
    for (int k = begin; k < end; ++k) {
      const Eigen::Vector3i& t = mesh.triangles[order[k]];
      for (int c = 0; c < 3; ++c) {
        lo = lo.cwiseMin(mesh.vertices[t[c]]);
        hi = hi.cwiseMax(mesh.vertices[t[c]]);
      }
    }
  }

  /// Centre, half size and bounding-sphere radius from the box (stored: the queries' hot path).
  static void set_sphere(MeshBvh::Node& node) {
    node.center = 0.5 * (node.lo + node.hi);
    node.half = 0.5 * (node.hi - node.lo);
    node.radius = node.half.norm();
  }

  /// Builds the subtree of order[begin, end); a node's box is its triangles' corners (leaf) or
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
    Eigen::Vector3d clo = centroid[order[begin]], chi = clo;
    for (int k = begin + 1; k < end; ++k) {
      clo = clo.cwiseMin(centroid[order[k]]);
      chi = chi.cwiseMax(centroid[order[k]]);
    }
    int axis = 0;
    (chi - clo).maxCoeff(&axis);
    const int mid = begin + (end - begin) / 2;
    if (split == MeshBvhSplit::kCornerSum)
      std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end,
                       [&](int a, int b) { return corner_sum[a][axis] < corner_sum[b][axis]; });
    else
      std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end,
                       [&](int a, int b) {
                         const double ca = centroid[a][axis], cb = centroid[b][axis];
                         return ca < cb || (ca == cb && a < b);
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

}  // namespace

MeshBvh build_mesh_bvh(const Mesh& mesh, int max_leaf_triangles, MeshBvhSplit split) {
  if (max_leaf_triangles < 1) throw std::invalid_argument("build_mesh_bvh: max_leaf_triangles < 1");
  MeshBvh bvh;
  bvh.vertices = mesh.vertices;
  const int n = int(mesh.triangles.size());
  if (n == 0) return bvh;
  Builder b{mesh, max_leaf_triangles, split, {}, {}, {}, bvh};
  b.centroid.resize(n);
  if (split == MeshBvhSplit::kCornerSum) b.corner_sum.resize(n);
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector3i& t = mesh.triangles[k];
    const Eigen::Vector3d sum = mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]];
    if (split == MeshBvhSplit::kCornerSum) {
      b.corner_sum[k] = sum;
      b.centroid[k] = sum * (1.0 / 3.0);
    } else {
      b.centroid[k] = sum / 3.0;
    }
  }
  b.order.resize(n);
  std::iota(b.order.begin(), b.order.end(), 0);
  // Median splits leave at least ⌈max_leaf / 2⌉ triangles in a leaf (fewer only for a mesh
  // that small): at most 2·leaves − 1 nodes, reserved at once (no regrowth copy).
  const int min_leaf = std::max(1, (max_leaf_triangles + 1) / 2);
  bvh.nodes.reserve(size_t(2 * (n / min_leaf + 1)));
  b.build(0, n);
  bvh.triangle_ids = b.order;
  bvh.triangles.resize(n);
  for (int k = 0; k < n; ++k) bvh.triangles[k] = mesh.triangles[b.order[k]];
  return bvh;
}

MeshBvh build_object_bvh(const Mesh& mesh) {
  Mesh usable;
  usable.name = mesh.name;
  usable.vertices = mesh.vertices;
  usable.triangles.reserve(mesh.triangles.size());
  std::vector<int> ids;  // usable triangle -> mesh triangle
  ids.reserve(mesh.triangles.size());
  for (size_t k = 0; k < mesh.triangles.size(); ++k) {
    const Eigen::Vector3i& t = mesh.triangles[k];
    const Eigen::Vector3d& a = mesh.vertices[static_cast<size_t>(t[0])];
    const Eigen::Vector3d& b = mesh.vertices[static_cast<size_t>(t[1])];
    const Eigen::Vector3d& c = mesh.vertices[static_cast<size_t>(t[2])];
    if ((b - a).cross(c - a).squaredNorm() <= 0.0) continue;
    usable.triangles.push_back(t);
    ids.push_back(static_cast<int>(k));
  }
  const int leaf = static_cast<int>(usable.triangles.size()) > kLargeMeshTriangles
                       ? kLargeMeshLeafTriangles
                       : 4;
  MeshBvh bvh = build_mesh_bvh(usable, leaf, MeshBvhSplit::kCornerSum);
  for (int& id : bvh.triangle_ids) id = ids[static_cast<size_t>(id)];
  return bvh;
}

}  // namespace cordgrasp
