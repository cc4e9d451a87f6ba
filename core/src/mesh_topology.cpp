#include "cordgrasp/core/mesh_topology.h"

#include <numeric>
#include <vector>

#include "mesh_edges.h"

namespace cordgrasp {
namespace {

/// Union-find with path halving.
struct DisjointSets {
  std::vector<int> parent;
  explicit DisjointSets(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(int a, int b) { parent[find(a)] = find(b); }
};

}  // namespace

MeshTopology mesh_topology(const Mesh& mesh) {
  const detail::MeshEdges me = detail::build_mesh_edges(mesh);
  MeshTopology topo;
  topo.vertices = me.welded_vertices;
  topo.edges = me.edges;
  topo.triangles = int(mesh.triangles.size());
  topo.boundary_edges = me.boundary_edges;
  topo.non_manifold_edges = me.non_manifold_edges;
  for (int side = 0; side < 3 * topo.triangles; ++side) {
    const int other = me.twin[size_t(side)];
    if (other > side && me.forward(mesh, side) == me.forward(mesh, other)) ++topo.misoriented_edges;
  }
  DisjointSets sets(me.welded_vertices);
  for (const auto& t : mesh.triangles) {
    sets.unite(me.weld[t[0]], me.weld[t[1]]);
    sets.unite(me.weld[t[0]], me.weld[t[2]]);
  }
  for (int v = 0; v < me.welded_vertices; ++v)
    if (sets.find(v) == v) ++topo.components;
  topo.euler_characteristic = topo.vertices - topo.edges + topo.triangles;
  topo.closed = topo.triangles > 0 && topo.boundary_edges == 0 && topo.non_manifold_edges == 0;
  return topo;
}

}  // namespace cordgrasp
