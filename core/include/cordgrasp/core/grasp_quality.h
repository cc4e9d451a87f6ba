#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "cordgrasp/core/contact_model.h"
#include "cordgrasp/core/grasp.h"
#include "cordgrasp/core/mesh.h"
#include "cordgrasp/core/serialize.h"

namespace cordgrasp {

/// How force closure and ε are computed (docs/algorithm.md §8).
enum class QualityMode {
  kTextbook,  ///< real μ; FC iff the origin is inside the hull by more than min_epsilon;
              ///< ε = origin→hull distance
  kSimox,     ///< Simox compat: μ_eff = 1 (45° cones), FC tolerance 1e-4, ε = GWS/OWS ratio of
              ///< facet distances from the hull's vertex centroid
};

/// "textbook" or "simox".
const char* to_string(QualityMode mode);

/// Parses "textbook" / "simox". @throws std::invalid_argument on anything else.
QualityMode parse_quality_mode(const std::string& text);

/// Old name of parse_quality_mode.
inline QualityMode quality_mode_from_string(const std::string& text) {
  return parse_quality_mode(text);
}

/// Parameters of the grasp wrench space (docs/algorithm.md §8).
struct QualityParams {
  ContactModel contact;  ///< μ (textbook mode) and cone edges
  /// Textbook mode: force closure needs ε above this. Grasps whose contacts leave the origin on
  /// the hull's boundary (e.g. two collinear opposed contacts plus one) come out of the joggled
  /// hull with ε ~ 1e-11; they are not force closure.
  double min_epsilon = 1e-8;
  QualityMode mode = QualityMode::kTextbook;
  double simox_mu_eff = 1.0;         ///< cone slope Simox really uses (45° half-angle)
  double simox_fc_tolerance = 1e-4;  ///< Simox accepts max facet offset ≤ this as FC
  int simox_ows_faces = 300;         ///< faces sampled for the object wrench space
  std::uint64_t seed = 1;            ///< seeds the OWS face sampling (simox mode)

  /// Visits every field in declaration order (core/serialize.h).
  template <typename Archive>
  void Serialize(Archive* a) {
    visit_fields(a, CORDGRASP_NVP(contact), CORDGRASP_NVP(min_epsilon), CORDGRASP_NVP(mode),
                 CORDGRASP_NVP(simox_mu_eff), CORDGRASP_NVP(simox_fc_tolerance),
                 CORDGRASP_NVP(simox_ows_faces), CORDGRASP_NVP(seed));
  }
};

/// 6D wrench (force; λ·torque).
using Wrench = Eigen::Matrix<double, 6, 1>;

/// Object-dependent constants of the wrench space, computed once per object
/// (docs/algorithm.md §8).
struct WrenchSpaceObject {
  Eigen::Vector3d center_O = Eigen::Vector3d::Zero();  ///< torque reference c: vertex mean [m]
  double torque_scale_per_m = 1.0;                     ///< λ = 2/L, L = longest AABB side [1/m]
  double ows_min_offset = 0.0;  ///< simox mode: OWS min facet distance from its centroid
};

/// Computes c, λ and (simox mode) the OWS of 300 seeded random faces (docs/algorithm.md §8).
/// @throws std::invalid_argument for an empty mesh.
WrenchSpaceObject prepare_wrench_space(const Mesh& mesh, const QualityParams& params);

/// Cone-edge wrenches of one contact: force directions unit(−n + μ(cos φ_j t1 + sin φ_j t2)),
/// φ_j = 2πj/edges, pushing into the object, torque λ·(p − c) × f (docs/algorithm.md §8). With
/// soft_finger_radius_m = ρ > 0 each edge comes twice, with torque ± λ·μ·ρ·(f·(−n))·(−n) added
/// (torsional friction of a soft finger).
std::vector<Wrench> contact_wrenches(const Eigen::Vector3d& p_O, const Eigen::Vector3d& n_O,
                                     double mu, int edges, const Eigen::Vector3d& center_O,
                                     double torque_scale_per_m, double soft_finger_radius_m = 0.0);

/// Convex hull of 6D wrenches via Qhull ("QJ"), as signed facet offsets (docs/algorithm.md §8).
struct WrenchHull {
  bool valid = false;                  ///< false: < 7 affinely independent points or Qhull failed
  double max_offset = 0.0;             ///< max_f b_f: the origin is inside iff < 0
  double min_origin_distance = 0.0;    ///< min_f (−b_f): origin to the nearest facet plane
  double min_centroid_distance = 0.0;  ///< min_f distance from the hull's vertex centroid
  int facets = 0;
};

/// Hull of `wrenches` (6D, Qhull reentrant API, options "QJ").
WrenchHull wrench_hull(const std::vector<Wrench>& wrenches);

/// Force closure and ε of a grasp.
struct GraspQuality {
  bool force_closure = false;
  double epsilon = 0.0;  ///< textbook: origin→hull distance; simox: GWS/OWS ratio; 0 if not FC
  WrenchHull hull;       ///< raw hull figures (valid = false: fewer than 2 contacts or a
                         ///< degenerate hull)
};

/// Force-closure test and ε of contacts on an object (docs/algorithm.md §8). Fewer than 2
/// contacts, or a degenerate hull, give not-FC and ε = 0.
GraspQuality evaluate_grasp_quality(const std::vector<Contact>& contacts,
                                    const WrenchSpaceObject& object, const QualityParams& params);

}  // namespace cordgrasp
