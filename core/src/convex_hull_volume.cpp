#include "cordgrasp/core/convex_hull_volume.h"

#include <libqhullcpp/Qhull.h>
#include <libqhullcpp/QhullError.h>
#include <libqhullcpp/QhullFacet.h>
#include <libqhullcpp/QhullFacetList.h>
#include <libqhullcpp/QhullVertex.h>
#include <libqhullcpp/QhullVertexSet.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "cordgrasp/core/mesh_properties.h"

namespace cordgrasp {

// Qhull's C++ front end (qhullcpp) is used rather than the bare reentrant C API: once
// libqhullcpp is linked, its qh_fprintf replaces libqhull_r's and aborts the process when a
// plain C qhT reports an error (QH10025), e.g. for flat input.

SolidVolume convex_hull_volume(const Mesh& mesh, std::vector<Eigen::Vector3d>* hull_vertices) {
  return convex_hull_volume(referenced_vertices(mesh), hull_vertices);
}

SolidVolume convex_hull_volume(const std::vector<Eigen::Vector3d>& input,
                               std::vector<Eigen::Vector3d>* hull_vertices) {
  if (hull_vertices) hull_vertices->clear();
  std::vector<realT> points;
  points.reserve(3 * input.size());
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& v : input) {
    points.insert(points.end(), {v.x(), v.y(), v.z()});
    sum += v;
  }
  const int count = static_cast<int>(input.size());
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

std::vector<Eigen::Vector3d> column_extreme_points(const std::vector<Eigen::Vector3d>& points,
                                                   int cells) {
  if (points.size() < 4 || cells < 1) return points;
  Eigen::Vector3d lo = points.front(), hi = points.front();
  for (const Eigen::Vector3d& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double width = (hi - lo).maxCoeff() / cells;
  if (!(width > 0.0)) return points;
  Eigen::Vector3i n;
  for (int a = 0; a < 3; ++a) n[a] = std::min(cells, static_cast<int>((hi[a] - lo[a]) / width)) + 1;
  auto cell = [&](const Eigen::Vector3d& p, int a) {
    return std::min(n[a] - 1, static_cast<int>((p[a] - lo[a]) / width));
  };
  std::vector<char> kept(points.size(), 0);
  for (int a = 0; a < 3; ++a) {  // columns along axis a
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    std::vector<int> low(static_cast<size_t>(n[b]) * n[c], -1), high(low.size(), -1);
    for (int i = 0; i < static_cast<int>(points.size()); ++i) {
      const Eigen::Vector3d& p = points[static_cast<size_t>(i)];
      const size_t column = static_cast<size_t>(cell(p, b)) * n[c] + cell(p, c);
      int& l = low[column];
      int& h = high[column];
      if (l < 0 || p[a] < points[static_cast<size_t>(l)][a]) l = i;
      if (h < 0 || p[a] > points[static_cast<size_t>(h)][a]) h = i;
    }
    for (size_t k = 0; k < low.size(); ++k)
      if (low[k] >= 0) kept[static_cast<size_t>(low[k])] = kept[static_cast<size_t>(high[k])] = 1;
  }
  std::vector<Eigen::Vector3d> out;
  for (size_t i = 0; i < points.size(); ++i)
    if (kept[i]) out.push_back(points[i]);
  return out;
}

}  // namespace cordgrasp
