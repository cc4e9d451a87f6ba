#include "cordgrasp/core/grasp_quality.h"

#include <libqhullcpp/Qhull.h>
#include <libqhullcpp/QhullError.h>

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <sstream>
#include <stdexcept>

#include "cordgrasp/core/enum_names.h"
#include "cordgrasp/core/mesh_properties.h"
#include "glpk_problem.h"

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

namespace cordgrasp {

namespace {

constexpr int kDim = 6;
// Relative singular-value threshold below which the wrench set is taken as lower-dimensional.
constexpr double kRankTolerance = 1e-9;

// Unit tangent pair (t1, t2) ⊥ n, deterministic: t1 is the coordinate axis least aligned with n,
// projected onto the tangent plane; t2 = n × t1.
void tangent_basis(const Eigen::Vector3d& n, Eigen::Vector3d& t1, Eigen::Vector3d& t2) {
  Eigen::Index axis = 0;
  n.cwiseAbs().minCoeff(&axis);
  const Eigen::Vector3d e = Eigen::Vector3d::Unit(axis);
  t1 = (e - e.dot(n) * n).normalized();
  t2 = n.cross(t1);
}

bool full_rank(const std::vector<Wrench>& w) {
  if (w.size() < kDim + 1) return false;
  Wrench mean = Wrench::Zero();
  for (const Wrench& x : w) mean += x;
  mean /= static_cast<double>(w.size());
  Eigen::Matrix<double, kDim, Eigen::Dynamic> m(kDim, static_cast<Eigen::Index>(w.size()));
  for (size_t i = 0; i < w.size(); ++i) m.col(static_cast<Eigen::Index>(i)) = w[i] - mean;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(m);
  const auto& s = svd.singularValues();
  if (s(0) <= 0.0) return false;
  return s(kDim - 1) > kRankTolerance * s(0);
}

// Whether some combination of the wrenches with every weight ≥ 1 (strictly positive, up to
// scale) is zero: with full rank, exactly when the origin lies inside their hull. A linear
// program, far cheaper than the hull: evaluate_grasp_quality builds the hull (for ε) only for
// wrench sets that pass. A simplex that fails says yes (the hull decides).
bool zero_in_positive_span(const std::vector<Wrench>& w) {
  Eigen::MatrixXd a(kDim, static_cast<Eigen::Index>(w.size()));
  for (size_t k = 0; k < w.size(); ++k) a.col(static_cast<Eigen::Index>(k)) = w[k];
  GlpkProblem lp = make_glpk_problem(a);
  for (int r = 1; r <= kDim; ++r) glp_set_row_bnds(lp.get(), r, GLP_FX, 0.0, 0.0);
  for (int c = 1; c <= static_cast<int>(w.size()); ++c)
    glp_set_col_bnds(lp.get(), c, GLP_LO, 1.0, 0.0);
  return solve_glpk_problem(lp.get()) != GLP_NOFEAS;
}

double mu_for(const QualityParams& params) {
  return params.mode == QualityMode::kSimox ? params.simox_mu_eff : params.contact.mu;
}

}  // namespace

constexpr EnumName<QualityMode> kQualityModeNames[] = {{QualityMode::kTextbook, "textbook"},
                                                        {QualityMode::kSimox, "simox"}};

const char* to_string(QualityMode mode) { return enum_to_string(mode, kQualityModeNames); }

QualityMode parse_quality_mode(const std::string& text) {
  return parse_enum(text, kQualityModeNames, "quality mode");
}

std::vector<Wrench> contact_wrenches(const Eigen::Vector3d& p_O, const Eigen::Vector3d& n_O,
                                     double mu, int edges, const Eigen::Vector3d& center_O,
                                     double torque_scale_per_m, double soft_finger_radius_m) {
  if (edges < 1) throw std::invalid_argument("contact_wrenches: edges must be >= 1");
  const Eigen::Vector3d n = n_O.normalized();
  Eigen::Vector3d t1, t2;
  tangent_basis(n, t1, t2);
  const Eigen::Vector3d r = p_O - center_O;
  std::vector<Wrench> out;
  out.reserve(static_cast<size_t>(edges));
  for (int j = 0; j < edges; ++j) {
    const double phi = 2.0 * M_PI * j / edges;
    const Eigen::Vector3d f = (-n + mu * (std::cos(phi) * t1 + std::sin(phi) * t2)).normalized();
    Wrench w;
    w.head<3>() = f;
    w.tail<3>() = torque_scale_per_m * r.cross(f);
    if (soft_finger_radius_m > 0.0) {
      const Eigen::Vector3d torsion =
          torque_scale_per_m * mu * soft_finger_radius_m * f.dot(-n) * (-n);
      Wrench w2 = w;
      w.tail<3>() += torsion;
      w2.tail<3>() -= torsion;
      out.push_back(w2);
    }
    out.push_back(w);
  }
  return out;
}

WrenchHull wrench_hull(const std::vector<Wrench>& wrenches) {
  WrenchHull out;
  if (!full_rank(wrenches)) return out;
  std::vector<coordT> coords(wrenches.size() * kDim);
  for (size_t i = 0; i < wrenches.size(); ++i)
    for (int d = 0; d < kDim; ++d) coords[i * kDim + d] = wrenches[i][d];

  // Qhull's C++ front end: with libqhullcpp linked, errors of a bare C qhT abort the process
  // (see convex_hull_volume.cpp); orgQhull::Qhull turns them into exceptions.
  orgQhull::Qhull qhull;
  std::ostringstream messages;  // keep Qhull's diagnostics off stderr
  qhull.setErrorStream(&messages);
  qhull.setOutputStream(&messages);
  try {
    qhull.runQhull("", kDim, static_cast<int>(wrenches.size()), coords.data(), "QJ Pp");
  } catch (const orgQhull::QhullError&) {
    return out;
  }
  qhT* qh = qhull.qh();
  // Vertex centroid of the hull (Simox's "center" of the convex hull).
  Wrench centroid = Wrench::Zero();
  int nvertices = 0;
  vertexT* vertex;
  FORALLvertices {
    for (int d = 0; d < kDim; ++d) centroid[d] += vertex->point[d];
    ++nvertices;
  }
  if (nvertices > 0) centroid /= nvertices;
  out.max_offset = -std::numeric_limits<double>::infinity();
  out.min_origin_distance = std::numeric_limits<double>::infinity();
  out.min_centroid_distance = std::numeric_limits<double>::infinity();
  facetT* facet;
  FORALLfacets {
    const Eigen::Map<const Eigen::Matrix<coordT, kDim, 1>> a(facet->normal);
    const double b = facet->offset;
    out.max_offset = std::max(out.max_offset, b);
    out.min_origin_distance = std::min(out.min_origin_distance, -b);
    out.min_centroid_distance = std::min(out.min_centroid_distance, -(a.dot(centroid) + b));
    ++out.facets;
  }
  out.valid = out.facets > 0 && nvertices > 0;
  if (!out.valid) out = WrenchHull{};
  return out;
}

WrenchSpaceObject prepare_wrench_space(const Mesh& mesh, const QualityParams& params) {
  if (mesh.vertices.empty() || mesh.triangles.empty())
    throw std::invalid_argument("prepare_wrench_space: mesh '" + mesh.name + "' is empty");
  WrenchSpaceObject out;
  out.center_O = vertex_mean(mesh);
  const double longest = mesh_bounds(mesh).size().maxCoeff();
  if (!(longest > 0.0))
    throw std::invalid_argument("prepare_wrench_space: mesh '" + mesh.name + "' has zero size");
  out.torque_scale_per_m = 2.0 / longest;
  if (params.mode != QualityMode::kSimox) return out;

  // Object wrench space: cones at the centroids of up to `simox_ows_faces` random faces, normals
  // oriented away from the vertex mean (soup windings are unreliable).
  std::vector<int> faces(mesh.triangles.size());
  std::iota(faces.begin(), faces.end(), 0);
  std::mt19937_64 rng(params.seed);
  const size_t count = std::min(faces.size(), static_cast<size_t>(params.simox_ows_faces));
  for (size_t i = 0; i < count; ++i) {
    std::uniform_int_distribution<size_t> pick(i, faces.size() - 1);
    std::swap(faces[i], faces[pick(rng)]);
  }
  std::vector<Wrench> ows;
  for (size_t i = 0; i < count; ++i) {
    const Eigen::Vector3i& t = mesh.triangles[static_cast<size_t>(faces[i])];
    const Eigen::Vector3d& a = mesh.vertices[t[0]];
    const Eigen::Vector3d& b = mesh.vertices[t[1]];
    const Eigen::Vector3d& c = mesh.vertices[t[2]];
    Eigen::Vector3d n = (b - a).cross(c - a);
    if (n.norm() <= 0.0) continue;
    n.normalize();
    const Eigen::Vector3d p = (a + b + c) / 3.0;
    if ((p - out.center_O).dot(n) < 0.0) n = -n;
    const auto w = contact_wrenches(p, n, params.simox_mu_eff, params.contact.cone_edges,
                                    out.center_O, out.torque_scale_per_m);
    ows.insert(ows.end(), w.begin(), w.end());
  }
  const WrenchHull hull = wrench_hull(ows);
  out.ows_min_offset = hull.valid ? hull.min_centroid_distance : 0.0;
  return out;
}

GraspQuality evaluate_grasp_quality(const std::vector<Contact>& contacts,
                                    const WrenchSpaceObject& object, const QualityParams& params) {
  GraspQuality out;
  if (contacts.size() < 2) return out;
  const double mu = mu_for(params);
  std::vector<Wrench> w;
  w.reserve(contacts.size() * static_cast<size_t>(params.contact.cone_edges));
  for (const Contact& c : contacts) {
    const auto cw =
        contact_wrenches(c.p_O, c.n_O, mu, params.contact.cone_edges, object.center_O,
                         object.torque_scale_per_m, params.contact.soft_finger_radius_m);
    w.insert(w.end(), cw.begin(), cw.end());
  }
  // Textbook force closure needs the origin inside the hull: most attempts fail the cheap test.
  if (params.mode == QualityMode::kTextbook && !zero_in_positive_span(w)) return out;
  out.hull = wrench_hull(w);
  if (!out.hull.valid) return out;
  if (params.mode == QualityMode::kSimox) {
    out.force_closure = out.hull.max_offset <= params.simox_fc_tolerance;
    if (out.force_closure && object.ows_min_offset > 0.0)
      out.epsilon = out.hull.min_centroid_distance / object.ows_min_offset;
  } else {
    out.force_closure = out.hull.min_origin_distance > params.min_epsilon;
    if (out.force_closure) out.epsilon = out.hull.min_origin_distance;
  }
  return out;
}

}  // namespace cordgrasp
