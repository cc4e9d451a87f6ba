#include "cordgrasp/core/convex_hull_volume.h"

#include <libqhullcpp/Qhull.h>
#include <libqhullcpp/QhullError.h>
#include <libqhullcpp/QhullFacet.h>
#include <libqhullcpp/QhullFacetList.h>
#include <libqhullcpp/QhullVertex.h>
#include <libqhullcpp/QhullVertexSet.h>

#include <cmath>
#include <sstream>
#include <vector>

#include "cordgrasp/core/mesh_properties.h"

namespace cordgrasp {

// Qhull's C++ front end (qhullcpp) is used rather than the bare reentrant C API: once
// libqhullcpp is linked, its qh_fprintf replaces libqhull_r's and aborts the process when a
// plain C qhT reports an error (QH10025), e.g. for flat input.

SolidVolume convex_hull_volume(const Mesh& mesh, std::vector<Eigen::Vector3d>* hull_vertices) {
  if (hull_vertices) hull_vertices->clear();
  std::vector<char> used(mesh.vertices.size(), 0);
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) used[t[k]] = 1;
  std::vector<realT> points;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int count = 0;
  for (size_t i = 0; i < mesh.vertices.size(); ++i)
    if (used[i]) {
      const auto& v = mesh.vertices[i];
      points.insert(points.end(), {v.x(), v.y(), v.z()});
      sum += v;
      ++count;
    }
  SolidVolume out;
  out.center_of_mass_m = count > 0 ? Eigen::Vector3d(sum / count) : sum;
  if (count < 4) return out;

  orgQhull::Qhull qhull;
  std::ostringstream messages;  // keep Qhull's diagnostics off stderr
  qhull.setErrorStream(&messages);
  qhull.setOutputStream(&messages);
  try {
    qhull.runQhull("", 3, count, points.data(), "Qt");  // triangulated facets
  } catch (const orgQhull::QhullError&) {
    return out;  // flat or otherwise degenerate input: no volume
  }
  // Tetrahedra from an interior point to each facet; |volume| since the hull is convex and the
  // interior point inside it.
  const realT* interior = qhull.qh()->interior_point;
  const Eigen::Vector3d o(interior[0], interior[1], interior[2]);
  double volume = 0.0;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  for (const orgQhull::QhullFacet& facet : qhull.facetList()) {
    const orgQhull::QhullVertexSet vertices = facet.vertices();
    if (vertices.size() != 3) continue;  // "Qt" gives simplicial facets
    Eigen::Vector3d p[3];
    for (int k = 0; k < 3; ++k) {
      const realT* c = vertices[k].point().coordinates();
      p[k] = Eigen::Vector3d(c[0], c[1], c[2]);
    }
    const double v = std::abs((p[0] - o).dot((p[1] - o).cross(p[2] - o))) / 6.0;
    volume += v;
    moment += v * (o + p[0] + p[1] + p[2]) / 4.0;
  }
  if (volume > 0.0) {
    out.volume_m3 = volume;
    out.center_of_mass_m = moment / volume;
  }
  if (hull_vertices)
    for (const orgQhull::QhullVertex& v : qhull.vertexList()) {
      const realT* c = v.point().coordinates();
      hull_vertices->emplace_back(c[0], c[1], c[2]);
    }
  return out;
}

}  // namespace cordgrasp
