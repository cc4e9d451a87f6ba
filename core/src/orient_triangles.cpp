#include "cordgrasp/core/orient_triangles.h"

#include <deque>
#include <utility>
#include <vector>

#include "mesh_edges.h"

namespace cordgrasp {

OrientReport orient_triangles(Mesh& mesh) {
  const detail::MeshEdges me = detail::build_mesh_edges(mesh);
  const int nt = int(mesh.triangles.size());
  OrientReport report;
  std::vector<int> patch(nt, -1);
  std::vector<char> flip(nt, 0);
  std::vector<std::vector<int>> members;
  std::deque<int> queue;
  for (int seed = 0; seed < nt; ++seed) {
    if (patch[seed] >= 0) continue;
    const int p = int(members.size());
    members.emplace_back();
    patch[seed] = p;
    queue.push_back(seed);
    while (!queue.empty()) {
      const int t = queue.front();
      queue.pop_front();
      members[p].push_back(t);
      for (int s = 0; s < 3; ++s) {
        const int e = me.tri_edge[t][s];
        if (e < 0 || me.use_count(e) != 2) continue;
        const detail::EdgeUse u0 = me.uses[me.first_use[e]], u1 = me.uses[me.first_use[e] + 1];
        const detail::EdgeUse& mine = u0.tri == t ? u0 : u1;
        const detail::EdgeUse& other = u0.tri == t ? u1 : u0;
        if (other.tri == t) continue;
        // Consistent winding: the two triangles walk the shared edge in opposite directions.
        const bool mine_forward = mine.forward != bool(flip[t]);
        const char needed = char(other.forward == mine_forward);
        if (patch[other.tri] < 0) {
          patch[other.tri] = p;
          flip[other.tri] = needed;
          queue.push_back(other.tri);
        } else if (flip[other.tri] != needed) {
          report.orientable = false;
        }
      }
    }
  }
  report.patches = int(members.size());

  for (const auto& tris : members) {
    bool closed = true;
    int flips = 0;
    for (int t : tris) {
      flips += flip[t];
      for (int s = 0; s < 3; ++s) {
        const int e = me.tri_edge[t][s];
        if (e >= 0 && me.use_count(e) != 2) closed = false;
      }
    }
    bool toggle;
    if (closed) {
      ++report.closed_patches;
      // Signed volume relative to a vertex of the patch: positive means outward.
      const Eigen::Vector3d o = mesh.vertices[mesh.triangles[tris.front()][0]];
      double six_volume = 0.0;
      for (int t : tris) {
        const auto& tri = mesh.triangles[t];
        const Eigen::Vector3d a = mesh.vertices[tri[0]] - o;
        Eigen::Vector3d b = mesh.vertices[tri[1]] - o, c = mesh.vertices[tri[2]] - o;
        if (flip[t]) std::swap(b, c);
        six_volume += a.dot(b.cross(c));
      }
      toggle = six_volume < 0.0;
    } else {
      toggle = 2 * flips > int(tris.size());  // keep most triangles as authored
    }
    for (int t : tris) {
      if (toggle) flip[t] = !flip[t];
      if (flip[t]) {
        std::swap(mesh.triangles[t][1], mesh.triangles[t][2]);
        ++report.flipped;
      }
    }
  }
  return report;
}

}  // namespace cordgrasp
