#include "mesh_arrays.h"

#include <cmath>
#include <cstring>
#include <unordered_map>

namespace cordgrasp::render_detail {
namespace {

struct PositionHash {
  size_t operator()(const Eigen::Vector3d& p) const {
    size_t h = 1469598103934665603ull;
    for (int i = 0; i < 3; ++i) {
      const double v = p[i] == 0.0 ? 0.0 : p[i];  // +0 and −0 weld together
      std::uint64_t bits;
      std::memcpy(&bits, &v, sizeof bits);
      h = (h ^ bits) * 1099511628211ull;
    }
    return h;
  }
};

struct PositionEqual {
  bool operator()(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const { return a == b; }
};

double corner_angle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d u = a - p, v = b - p;
  const double nu = u.norm(), nv = v.norm();
  if (nu == 0.0 || nv == 0.0) return 0.0;
  return std::acos(std::clamp(u.dot(v) / (nu * nv), -1.0, 1.0));
}

}  // namespace

std::vector<float> smooth_vertex_array(const Mesh& mesh, double crease_angle_rad) {
  const size_t nf = mesh.triangles.size();
  const int nv = static_cast<int>(mesh.vertices.size());
  std::vector<Eigen::Vector3d> face_normal(nf, Eigen::Vector3d::Zero());
  // Welded vertex id of each corner.
  std::unordered_map<Eigen::Vector3d, int, PositionHash, PositionEqual> weld;
  weld.reserve(mesh.vertices.size());
  std::vector<int> welded_of_vertex(mesh.vertices.size());
  for (int i = 0; i < nv; ++i)
    welded_of_vertex[i] =
        weld.emplace(mesh.vertices[i], static_cast<int>(weld.size())).first->second;
  const int nw = static_cast<int>(weld.size());

  std::vector<int> count(nw + 1, 0);
  std::vector<char> valid(nf, 0);
  for (size_t f = 0; f < nf; ++f) {
    const Eigen::Vector3i& t = mesh.triangles[f];
    if ((t.array() < 0).any() || (t.array() >= nv).any()) continue;
    valid[f] = 1;
    const Eigen::Vector3d n = (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                                  .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
    const double len = n.norm();
    if (len > 0.0) face_normal[f] = n / len;
    for (int k = 0; k < 3; ++k) ++count[welded_of_vertex[t[k]] + 1];
  }
  for (int w = 0; w < nw; ++w) count[w + 1] += count[w];
  // Incident (face, corner) pairs per welded vertex, CSR.
  std::vector<std::pair<int, int>> incident(count[nw]);
  std::vector<int> fill(count.begin(), count.end() - 1);
  for (size_t f = 0; f < nf; ++f) {
    if (!valid[f]) continue;
    for (int k = 0; k < 3; ++k)
      incident[fill[welded_of_vertex[mesh.triangles[f][k]]]++] = {static_cast<int>(f), k};
  }

  const double cos_crease = std::cos(crease_angle_rad);
  std::vector<float> out;
  out.reserve(nf * 18);
  for (size_t f = 0; f < nf; ++f) {
    if (!valid[f]) continue;
    const Eigen::Vector3i& t = mesh.triangles[f];
    const Eigen::Vector3d& nf_unit = face_normal[f];
    for (int k = 0; k < 3; ++k) {
      const int w = welded_of_vertex[t[k]];
      Eigen::Vector3d n = Eigen::Vector3d::Zero();
      if (nf_unit.squaredNorm() > 0.0) {
        for (int i = count[w]; i < count[w + 1]; ++i) {
          const auto [g, c] = incident[i];
          const Eigen::Vector3d& ng = face_normal[g];
          if (ng.dot(nf_unit) < cos_crease) continue;
          const Eigen::Vector3i& tg = mesh.triangles[g];
          n += corner_angle(mesh.vertices[tg[c]], mesh.vertices[tg[(c + 1) % 3]],
                            mesh.vertices[tg[(c + 2) % 3]]) *
               ng;
        }
        const double len = n.norm();
        n = len > 0.0 ? Eigen::Vector3d(n / len) : nf_unit;
      }
      const Eigen::Vector3d& p = mesh.vertices[t[k]];
      out.insert(out.end(),
                 {static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z()),
                  static_cast<float>(n.x()), static_cast<float>(n.y()), static_cast<float>(n.z())});
    }
  }
  return out;
}

Mesh make_unit_cone_mesh(bool closed_arrow_head, int segments) {
  Mesh m;
  m.name = closed_arrow_head ? "unit_arrow_head" : "unit_cone";
  const double z_apex = closed_arrow_head ? 1.0 : 0.0, z_base = closed_arrow_head ? 0.0 : 1.0;
  m.vertices.emplace_back(0.0, 0.0, z_apex);
  for (int i = 0; i < segments; ++i) {
    const double a = 2.0 * M_PI * i / segments;
    m.vertices.emplace_back(std::cos(a), std::sin(a), z_base);
  }
  const int base_center = static_cast<int>(m.vertices.size());
  m.vertices.emplace_back(0.0, 0.0, z_base);
  for (int i = 0; i < segments; ++i) {
    const int a = 1 + i, b = 1 + (i + 1) % segments;
    if (closed_arrow_head) {
      m.triangles.emplace_back(0, a, b);            // lateral, outward
      m.triangles.emplace_back(base_center, b, a);  // base cap, facing −z
    } else {
      m.triangles.emplace_back(0, b, a);  // lateral, outward (apex below the base)
    }
  }
  if (!closed_arrow_head) m.vertices.pop_back();
  return m;
}

}  // namespace cordgrasp::render_detail
