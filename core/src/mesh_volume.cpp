#include "cordgrasp/core/mesh_volume.h"

#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/core/mesh_topology.h"
#include "cordgrasp/core/orient_triangles.h"

namespace cordgrasp {

std::optional<SolidVolume> closed_mesh_volume(const Mesh& mesh) {
  if (!mesh_topology(mesh).closed) return std::nullopt;
  Mesh oriented = mesh;
  if (!orient_triangles(oriented).orientable) return std::nullopt;
  // Divergence theorem: sum of signed tetrahedra (o, a, b, c), o = vertex mean for conditioning.
  const Eigen::Vector3d o = vertex_mean(oriented);
  double six_volume = 0.0;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  // Σ 6V_i · (a + b + c − 3o)
  for (const auto& t : oriented.triangles) {
    const Eigen::Vector3d a = oriented.vertices[t[0]] - o;
    const Eigen::Vector3d b = oriented.vertices[t[1]] - o;
    const Eigen::Vector3d c = oriented.vertices[t[2]] - o;
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
