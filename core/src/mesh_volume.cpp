#include "cordgrasp/core/mesh_volume.h"

#include "cordgrasp/core/mesh_properties.h"
#include "mesh_edges.h"

namespace cordgrasp {

std::optional<SolidVolume> closed_mesh_volume(const Mesh& mesh) {
  // One edge table for the closed test and the orientation; the mesh is read, not copied.
  std::vector<char> flip;
  {
    const detail::MeshEdges me = detail::build_mesh_edges(mesh);
    if (mesh.triangles.empty() || !me.every_edge_used_twice()) return std::nullopt;
    detail::OrientationFlips flips = detail::orientation_flips(mesh, me);
    if (!flips.orientable) return std::nullopt;
    flip = std::move(flips.flip);
  }
  // Divergence theorem: sum of signed tetrahedra (o, a, b, c), o = vertex mean for conditioning,
  // over the triangles as orient_triangles() would wind them.
  const Eigen::Vector3d o = vertex_mean(mesh);
  double six_volume = 0.0;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  // Σ 6V_i · (a + b + c − 3o)
  for (size_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto& t = mesh.triangles[i];
    const Eigen::Vector3d a = mesh.vertices[t[0]] - o;
    const Eigen::Vector3d b = mesh.vertices[flip[i] ? t[2] : t[1]] - o;
    const Eigen::Vector3d c = mesh.vertices[flip[i] ? t[1] : t[2]] - o;
    const double v6 = a.dot(b.cross(c));
    six_volume += v6;
    moment += v6 * (a + b + c);
  }
  if (!(six_volume > 0.0)) return std::nullopt;
  SolidVolume out;
  out.volume_m3 = six_volume / 6.0;
  out.center_of_mass_m = o + moment / (4.0 * six_volume);
  return out;
}

}  // namespace cordgrasp
