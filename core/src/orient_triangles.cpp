#include "cordgrasp/core/orient_triangles.h"

#include <utility>
#include <vector>

#include "huge_pages.h"
#include "mesh_edges.h"

namespace cordgrasp {

namespace detail {

OrientationFlips orientation_flips(const Mesh& mesh, const MeshEdges& me) {
  const int nt = int(mesh.triangles.size());
  OrientationFlips out;
  std::vector<char>& flip = out.flip;
  assign_huge(flip, size_t(nt), char(0));
  std::vector<int> patch;
  assign_huge(patch, size_t(nt), -1);
  // Breadth-first over each patch: `order` is the queue, and holds the triangles patch by
  // patch in the order they were reached (patch p's are order[first[p]] ... order[first[p+1]−1]).
  std::vector<int> order;
  reserve_huge(order, size_t(nt));
  std::vector<int> first;
  for (int seed = 0; seed < nt; ++seed) {
    if (patch[seed] >= 0) continue;
    const int p = int(first.size());
    first.push_back(int(order.size()));
    patch[seed] = p;
    order.push_back(seed);
    for (size_t head = size_t(first.back()); head < order.size(); ++head) {
      const int t = order[head];
      for (int s = 0; s < 3; ++s) {
        const int mine = 3 * t + s, other = me.twin[size_t(mine)];
        if (other < 0) continue;  // not an edge of exactly two sides
        const int other_tri = other / 3;
        if (other_tri == t) continue;
        // Consistent winding: the two triangles walk the shared edge in opposite directions.
        const bool mine_forward = me.forward(mesh, mine) != bool(flip[t]);
        const char needed = char(me.forward(mesh, other) == mine_forward);
        if (patch[other_tri] < 0) {
          patch[other_tri] = p;
          flip[other_tri] = needed;
          order.push_back(other_tri);
        } else if (flip[other_tri] != needed) {
          out.orientable = false;
        }
      }
    }
  }
  out.patches = int(first.size());
  first.push_back(int(order.size()));

  for (int p = 0; p < out.patches; ++p) {
    const size_t begin = size_t(first[size_t(p)]), end = size_t(first[size_t(p) + 1]);
    bool closed = true;
    int flips = 0;
    for (size_t k = begin; k < end; ++k) {
      const int t = order[k];
      flips += flip[t];
      for (int s = 0; s < 3; ++s) {
        const int other = me.twin[size_t(3 * t + s)];
        if (other == MeshEdges::kBoundary || other == MeshEdges::kNonManifold) closed = false;
      }
    }
    bool toggle;
    if (closed) {
      ++out.closed_patches;
      // Signed volume relative to a vertex of the patch: positive means outward.
      const Eigen::Vector3d o = mesh.vertices[mesh.triangles[order[begin]][0]];
      double six_volume = 0.0;
      for (size_t k = begin; k < end; ++k) {
        const int t = order[k];
        const auto& tri = mesh.triangles[t];
        const Eigen::Vector3d a = mesh.vertices[tri[0]] - o;
        Eigen::Vector3d b = mesh.vertices[tri[1]] - o, c = mesh.vertices[tri[2]] - o;
        if (flip[t]) std::swap(b, c);
        six_volume += a.dot(b.cross(c));
      }
      toggle = six_volume < 0.0;
    } else {
      toggle = 2 * flips > int(end - begin);  // keep most triangles as authored
    }
    if (toggle)
      for (size_t k = begin; k < end; ++k) flip[order[k]] = !flip[order[k]];
  }
  return out;
}

}  // namespace detail

OrientReport orient_triangles(Mesh& mesh) {
  const detail::OrientationFlips flips =
      detail::orientation_flips(mesh, detail::build_mesh_edges(mesh));
  OrientReport report;
  report.patches = flips.patches;
  report.closed_patches = flips.closed_patches;
  report.orientable = flips.orientable;
  for (size_t t = 0; t < mesh.triangles.size(); ++t)
    if (flips.flip[t]) {
      std::swap(mesh.triangles[t][1], mesh.triangles[t][2]);
      ++report.flipped;
    }
  return report;
}

}  // namespace cordgrasp
