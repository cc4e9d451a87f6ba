#include "cordgrasp/core/balanced_contact_forces.h"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>

namespace cordgrasp {

namespace {

/// Singular values below this × the largest count as zero (rank of the grasp matrix).
constexpr double kRankTolerance = 1e-9;
/// Normal components below this × the largest do not press.
constexpr double kMinRelativePress = 1e-6;

Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

/// Alternating projections at most (each costs O(k²) for k contacts).
constexpr int kMaxProjections = 2000;

/// Closest point to `f` of the cone ‖f_t‖ ≤ μ·(f_n − 1), f_n = −f·n: the friction cone of
/// inward normal −n with its apex at a unit press.
Eigen::Vector3d project_to_pressing_cone(const Eigen::Vector3d& f, const Eigen::Vector3d& n,
                                         double mu) {
  const double normal = -f.dot(n) - 1.0;
  const Eigen::Vector3d tangent = f + (normal + 1.0) * n;
  const double t = tangent.norm();
  if (t <= mu * normal) return f;                          // inside
  if (mu * t <= -normal) return -n;                        // behind the apex: the apex
  const double s = (normal + mu * t) / (1.0 + mu * mu);    // onto the cone's surface
  const Eigen::Vector3d unit_t = tangent / t;
  return -(s + 1.0) * n + mu * s * unit_t;
}

/// Whether every 3-block of `f` presses along −n and lies within its friction cone.
bool within_cones(const std::vector<Contact>& contacts, const Eigen::VectorXd& f, double mu) {
  for (size_t i = 0; i < contacts.size(); ++i) {
    const Eigen::Vector3d fc = f.segment<3>(3 * static_cast<Eigen::Index>(i));
    const Eigen::Vector3d n = contacts[i].n_O.normalized();
    const double normal = -fc.dot(n);
    if (!(normal > 0.0) || (fc + normal * n).norm() > mu * normal) return false;
  }
  return true;
}

}  // namespace

BalancedContactForces balanced_contact_forces(const std::vector<Contact>& contacts, double mu) {
  BalancedContactForces out;
  const Eigen::Index k = static_cast<Eigen::Index>(contacts.size());
  if (k < 2) return out;
  // Grasp matrix G (6 × 3k): total force and moment about the contacts' mean. Its null space
  // is the same for any reference point and row scaling; the mean keeps it well conditioned.
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const Contact& c : contacts) centre += c.p_O;
  centre /= static_cast<double>(k);
  Eigen::MatrixXd G(6, 3 * k);
  Eigen::VectorXd press(3 * k);
  for (Eigen::Index i = 0; i < k; ++i) {
    const Contact& c = contacts[static_cast<size_t>(i)];
    G.block<3, 3>(0, 3 * i).setIdentity();
    G.block<3, 3>(3, 3 * i) = cross_matrix(c.p_O - centre);
    press.segment<3>(3 * i) = -c.n_O.normalized();
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(G, Eigen::ComputeFullV);
  const Eigen::VectorXd& sigma = svd.singularValues();
  Eigen::Index rank = 0;
  for (Eigen::Index i = 0; i < sigma.size(); ++i)
    if (sigma[i] > kRankTolerance * sigma[0]) ++rank;
  const Eigen::MatrixXd null = svd.matrixV().rightCols(3 * k - rank);
  if (null.cols() == 0) return out;
  Eigen::VectorXd f = null * (null.transpose() * press);
  if (!within_cones(contacts, f, mu)) {
    // Alternating projections between the balanced forces (a subspace) and the friction cones
    // with their apex moved to a unit press (convex): they converge to a force in both when
    // the contacts can be squeezed within their cones at all.
    for (int iteration = 0; iteration < kMaxProjections; ++iteration) {
      for (Eigen::Index i = 0; i < k; ++i)
        f.segment<3>(3 * i) = project_to_pressing_cone(
            f.segment<3>(3 * i), contacts[static_cast<size_t>(i)].n_O.normalized(), mu);
      f = null * (null.transpose() * f);
      if (within_cones(contacts, f, mu)) break;
    }
  }

  double largest_press = 0.0;
  for (Eigen::Index i = 0; i < k; ++i)
    largest_press = std::max(largest_press, -f.segment<3>(3 * i).dot(contacts[static_cast<size_t>(i)].n_O.normalized()));
  if (!(largest_press > 0.0)) return out;
  out.cone_margin = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < k; ++i) {
    const Eigen::Vector3d n = contacts[static_cast<size_t>(i)].n_O.normalized();
    const Eigen::Vector3d fc = f.segment<3>(3 * i) / largest_press;
    const double normal = -fc.dot(n);
    const double tangential = (fc + normal * n).norm();
    const double size = fc.norm();
    const double margin =
        normal < kMinRelativePress ? -1.0 : (mu * normal - tangential) / std::max(size, 1e-300);
    out.cone_margin = std::min(out.cone_margin, margin);
    out.forces_O.push_back(fc);
  }
  return out;
}

}  // namespace cordgrasp
