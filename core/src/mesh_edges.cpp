#include "mesh_edges.h"

#include <algorithm>
#include <numeric>

#include "weld_table.h"

namespace cordgrasp::detail {

MeshEdges build_mesh_edges(const Mesh& mesh) {
  MeshEdges out;
  const int nv = int(mesh.vertices.size());
  const int nt = int(mesh.triangles.size());

  // Weld: referenced vertices with equal coordinates share an id (ids in vertex order).
  std::vector<char> used(nv, 0);
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) used[t[k]] = 1;
  out.weld.assign(nv, -1);
  {
    WeldTable table{static_cast<size_t>(nv)};
    const auto point_of = [&](int i) -> const Eigen::Vector3d& { return mesh.vertices[i]; };
    for (int i = 0; i < nv; ++i) {
      if (!used[i]) continue;
      const int same = table.find_or_insert(mesh.vertices[i], i, point_of);
      out.weld[i] = same >= 0 ? out.weld[same] : out.welded_vertices++;
    }
  }

  // Undirected edges, bucketed by their lower welded id (counting sort, linear time); each
  // bucket holds (hi, 3·triangle + side) in triangle order, then is stably sorted by hi: the
  // uses of an edge come in (triangle, side) order.
  const auto side_ends = [&](int t, int s) {
    return std::array<int, 2>{out.weld[mesh.triangles[t][s]],
                              out.weld[mesh.triangles[t][(s + 1) % 3]]};
  };
  std::vector<int> bucket(size_t(out.welded_vertices) + 1, 0);
  for (int t = 0; t < nt; ++t)
    for (int s = 0; s < 3; ++s) {
      const auto [a, b] = side_ends(t, s);
      if (a != b) ++bucket[size_t(std::min(a, b)) + 1];
    }
  std::partial_sum(bucket.begin(), bucket.end(), bucket.begin());
  struct Entry {
    int hi, side_code;  // side_code = 3·triangle + side
  };
  std::vector<Entry> entries(size_t(bucket.back()));
  {
    std::vector<int> fill(bucket.begin(), bucket.end() - 1);
    for (int t = 0; t < nt; ++t)
      for (int s = 0; s < 3; ++s) {
        const auto [a, b] = side_ends(t, s);
        if (a == b) continue;  // collapsed side of a degenerate triangle
        entries[size_t(fill[size_t(std::min(a, b))]++)] = {std::max(a, b), 3 * t + s};
      }
  }
  const auto by_hi = [](const Entry& x, const Entry& y) { return x.hi < y.hi; };
  out.tri_edge.assign(nt, {-1, -1, -1});
  out.uses.reserve(entries.size());
  // A closed surface uses each edge twice: reserving half the uses avoids the growth copies
  // (a scan of millions of triangles) in the common case.
  out.edges.reserve(entries.size() / 2 + 1);
  out.first_use.reserve(entries.size() / 2 + 2);
  for (int lo = 0; lo < out.welded_vertices; ++lo) {
    Entry* first = entries.data() + bucket[size_t(lo)];
    Entry* last = entries.data() + bucket[size_t(lo) + 1];
    if (last - first <= 32) {  // insertion sort: stable, and buckets are small on real meshes
      for (Entry* k = first + 1; k < last; ++k)
        for (Entry* j = k; j > first && by_hi(*j, *(j - 1)); --j) std::swap(*j, *(j - 1));
    } else {
      std::stable_sort(first, last, by_hi);
    }
    for (Entry* k = first; k < last; ++k) {
      if (k == first || k->hi != (k - 1)->hi) {
        out.edges.push_back({lo, k->hi});
        out.first_use.push_back(int(out.uses.size()));
      }
      const int t = k->side_code / 3, s = k->side_code % 3;
      out.tri_edge[t][s] = int(out.edges.size()) - 1;
      out.uses.push_back({t, side_ends(t, s)[0] < side_ends(t, s)[1]});
    }
  }
  out.first_use.push_back(int(out.uses.size()));
  return out;
}

}  // namespace cordgrasp::detail
