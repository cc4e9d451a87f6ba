#include "mesh_edges.h"

#include <algorithm>
#include <numeric>

#include "huge_pages.h"
#include "weld_table.h"

namespace cordgrasp::detail {

MeshEdges build_mesh_edges(const Mesh& mesh) {
  MeshEdges out;
  const int nv = int(mesh.vertices.size());
  const int nt = int(mesh.triangles.size());

  // Weld: referenced vertices with equal coordinates share an id (ids in vertex order).
  assign_huge(out.weld, size_t(nv), -1);
  {
    std::vector<char> used(size_t(nv), 0);
    for (const auto& t : mesh.triangles)
      for (int k = 0; k < 3; ++k) used[size_t(t[k])] = 1;
    WeldTable table{static_cast<size_t>(nv)};
    const auto point_of = [&](int i) -> const Eigen::Vector3d& { return mesh.vertices[size_t(i)]; };
    for (int i = 0; i < nv; ++i) {
      if (i + kWeldLookAhead < nv) table.prefetch(mesh.vertices[size_t(i + kWeldLookAhead)]);
      if (!used[size_t(i)]) continue;
      const int same = table.find_or_insert(mesh.vertices[size_t(i)], i, point_of);
      out.weld[size_t(i)] = same >= 0 ? out.weld[size_t(same)] : out.welded_vertices++;
    }
  }

  // Sides bucketed by their edge's lower welded id (counting sort, linear time), each bucket
  // sorted by the higher id: the sides of one edge are then adjacent.
  const auto end_ids = [&](int code) {
    const Eigen::Vector3i& t = mesh.triangles[size_t(code / 3)];
    const int s = code % 3;
    const int a = out.weld[size_t(t[s])], b = out.weld[size_t(t[(s + 1) % 3])];
    return std::pair<int, int>{std::min(a, b), std::max(a, b)};
  };
  std::vector<int> bucket(size_t(out.welded_vertices) + 1, 0);
  for (int code = 0; code < 3 * nt; ++code) {
    const auto [lo, hi] = end_ids(code);
    if (lo != hi) ++bucket[size_t(lo) + 1];
  }
  std::partial_sum(bucket.begin(), bucket.end(), bucket.begin());
  std::vector<int> sides;
  reserve_huge(sides, size_t(bucket.back()));
  sides.resize(size_t(bucket.back()));
  {
    std::vector<int> fill(bucket.begin(), bucket.end() - 1);
    for (int code = 0; code < 3 * nt; ++code) {
      const auto [lo, hi] = end_ids(code);
      if (lo != hi) sides[size_t(fill[size_t(lo)]++)] = code;
    }
  }
  const auto hi_of = [&](int code) { return end_ids(code).second; };
  const auto by_hi = [&](int x, int y) { return hi_of(x) < hi_of(y); };
  assign_huge(out.twin, size_t(3) * size_t(nt), int(MeshEdges::kCollapsed));
  for (int lo = 0; lo < out.welded_vertices; ++lo) {
    int* first = sides.data() + bucket[size_t(lo)];
    int* last = sides.data() + bucket[size_t(lo) + 1];
    if (last - first <= 32) {  // insertion sort: buckets are small on real meshes
      for (int* k = first + 1; k < last; ++k)
        for (int* j = k; j > first && by_hi(*j, *(j - 1)); --j) std::swap(*j, *(j - 1));
    } else {
      std::sort(first, last, by_hi);
    }
    for (int* k = first; k < last;) {
      const int hi = hi_of(*k);
      int* group_end = k + 1;
      while (group_end < last && hi_of(*group_end) == hi) ++group_end;
      ++out.edges;
      const long uses = group_end - k;
      if (uses == 1) {
        out.twin[size_t(*k)] = MeshEdges::kBoundary;
        ++out.boundary_edges;
      } else if (uses == 2) {
        out.twin[size_t(k[0])] = k[1];
        out.twin[size_t(k[1])] = k[0];
      } else {
        for (int* j = k; j < group_end; ++j) out.twin[size_t(*j)] = MeshEdges::kNonManifold;
        ++out.non_manifold_edges;
      }
      k = group_end;
    }
  }
  return out;
}

}  // namespace cordgrasp::detail
