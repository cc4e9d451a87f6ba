#include "mesh_edges.h"

#include <algorithm>
#include <numeric>
#include <tuple>

namespace cordgrasp::detail {

MeshEdges build_mesh_edges(const Mesh& mesh) {
  MeshEdges out;
  const int nv = int(mesh.vertices.size());
  const int nt = int(mesh.triangles.size());

  // Weld: sort referenced vertices by coordinates, equal coordinates share an id.
  std::vector<char> used(nv, 0);
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) used[t[k]] = 1;
  std::vector<int> order;
  order.reserve(nv);
  for (int i = 0; i < nv; ++i)
    if (used[i]) order.push_back(i);
  const auto key = [&](int i) {
    const auto& p = mesh.vertices[i];
    return std::make_tuple(p.x(), p.y(), p.z());
  };
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key(a) < key(b); });
  out.weld.assign(nv, -1);
  for (size_t k = 0; k < order.size(); ++k) {
    if (k > 0 && key(order[k]) == key(order[k - 1])) {
      out.weld[order[k]] = out.welded_vertices - 1;
    } else {
      out.weld[order[k]] = out.welded_vertices++;
    }
  }

  // Undirected edges: (lo, hi, triangle, side) entries sorted, then grouped.
  struct Entry {
    int lo, hi, tri, side;
    bool forward;
  };
  std::vector<Entry> entries;
  entries.reserve(3 * size_t(nt));
  out.tri_edge.assign(nt, {-1, -1, -1});
  for (int t = 0; t < nt; ++t)
    for (int s = 0; s < 3; ++s) {
      const int a = out.weld[mesh.triangles[t][s]];
      const int b = out.weld[mesh.triangles[t][(s + 1) % 3]];
      if (a == b) continue;  // collapsed side of a degenerate triangle
      entries.push_back({std::min(a, b), std::max(a, b), t, s, a < b});
    }
  std::sort(entries.begin(), entries.end(), [](const Entry& x, const Entry& y) {
    return std::tie(x.lo, x.hi, x.tri, x.side) < std::tie(y.lo, y.hi, y.tri, y.side);
  });
  out.uses.reserve(entries.size());
  for (size_t k = 0; k < entries.size(); ++k) {
    const Entry& e = entries[k];
    if (k == 0 || e.lo != entries[k - 1].lo || e.hi != entries[k - 1].hi) {
      out.edges.push_back({e.lo, e.hi});
      out.first_use.push_back(int(out.uses.size()));
    }
    out.tri_edge[e.tri][e.side] = int(out.edges.size()) - 1;
    out.uses.push_back({e.tri, e.forward});
  }
  out.first_use.push_back(int(out.uses.size()));
  return out;
}

}  // namespace cordgrasp::detail
