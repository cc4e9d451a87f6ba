#include "cordgrasp/core/convex_hull_volume.h"

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

#include <cmath>
#include <cstdio>
#include <vector>

#include "cordgrasp/core/mesh_properties.h"

namespace cordgrasp {
namespace {

/// Owns a Qhull run; frees Qhull's memory on every path.
class QhullRun {
 public:
  QhullRun() {
    err_ = std::fopen("/dev/null", "w");  // Qhull reports flat input there; we handle it
    qh_zero(&qh_, err_);
  }
  ~QhullRun() {
    qh_freeqhull(&qh_, !qh_ALL);
    int curlong = 0, totlong = 0;
    qh_memfreeshort(&qh_, &curlong, &totlong);
    if (err_) std::fclose(err_);
  }
  QhullRun(const QhullRun&) = delete;
  QhullRun& operator=(const QhullRun&) = delete;

  /// Runs "qhull Qt" (triangulated facets) on n 3D points; false when Qhull fails (flat input).
  bool run(std::vector<coordT>& points) {
    char flags[] = "qhull Qt";
    const int n = int(points.size() / 3);
    return qh_new_qhull(&qh_, 3, n, points.data(), False, flags, nullptr, err_) == 0;
  }
  qhT* qh() { return &qh_; }

 private:
  qhT qh_{};
  std::FILE* err_ = nullptr;
};

}  // namespace

SolidVolume convex_hull_volume(const Mesh& mesh) {
  std::vector<char> used(mesh.vertices.size(), 0);
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) used[t[k]] = 1;
  std::vector<coordT> points;
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

  QhullRun run;
  if (!run.run(points)) return out;
  qhT* qh = run.qh();
  // Tetrahedra from an interior point to each (triangulated) facet; |volume| since the hull is
  // convex and the interior point inside it.
  const Eigen::Vector3d o(qh->interior_point[0], qh->interior_point[1], qh->interior_point[2]);
  double volume = 0.0;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  facetT* facet;
  FORALLfacets {
    Eigen::Vector3d p[3];
    int k = 0;
    vertexT *vertex, **vertexp;
    FOREACHvertex_(facet->vertices) {
      if (k < 3) p[k] = Eigen::Vector3d(vertex->point[0], vertex->point[1], vertex->point[2]);
      ++k;
    }
    if (k != 3) continue;  // Qt gives simplicial facets
    const double v = std::abs((p[0] - o).dot((p[1] - o).cross(p[2] - o))) / 6.0;
    volume += v;
    moment += v * (o + p[0] + p[1] + p[2]) / 4.0;
  }
  if (volume > 0.0) {
    out.volume_m3 = volume;
    out.center_of_mass_m = moment / volume;
  }
  return out;
}

}  // namespace cordgrasp
