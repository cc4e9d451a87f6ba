#include "cordgrasp/core/weight_margin.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "cordgrasp/core/grasp_quality.h"
#include "cordgrasp/core/kinematics.h"
#include "glpk_problem.h"

namespace cordgrasp {

double weight_margin(const HandModel& hand, const Grasp& grasp, const ContactModel& contact,
                     const StaticLoad& load, const Eigen::VectorXd& effort_limits,
                     double max_margin) {
  const Eigen::Index n = static_cast<Eigen::Index>(hand.joints.size());
  if (effort_limits.size() != n)
    throw std::invalid_argument("weight_margin: effort_limits has " +
                                std::to_string(effort_limits.size()) + " entries for " +
                                std::to_string(n) + " joints");
  if (grasp.contacts.empty() || !(load.weight_O_N.norm() > 0.0)) return 0.0;

  // Columns: the cone edges of every contact (unit force f, torque about the COM), then s.
  std::vector<Wrench> edges;
  std::vector<Eigen::VectorXd> edge_torques;
  const size_t nc = grasp.contacts.size();
  for (size_t c = 0; c < nc; ++c) {
    const Contact& k = grasp.contacts[c];
    // Joint torques of a unit force along each axis at this contact alone.
    Eigen::MatrixXd T(n, 3);
    for (int a = 0; a < 3; ++a) {
      std::vector<Eigen::Vector3d> forces(nc, Eigen::Vector3d::Zero());
      forces[c][a] = 1.0;
      T.col(a) = contact_force_torques(hand, grasp.q, grasp.X_OB, grasp.contacts, forces);
    }
    for (const Wrench& w : contact_wrenches(k.p_O, k.n_O, contact.mu, contact.cone_edges,
                                            load.com_O_m, 1.0, contact.soft_finger_radius_m)) {
      edges.push_back(w);
      edge_torques.push_back(T * w.head<3>());
    }
  }
  std::vector<int> bounded;  // joints with a torque row
  for (Eigen::Index j = 0; j < n; ++j) {
    const double e = effort_limits[j];
    if (!std::isfinite(e) || e <= 0.0) continue;
    bool loaded = false;
    for (const Eigen::VectorXd& t : edge_torques) loaded = loaded || std::abs(t[j]) > 0.0;
    if (loaded) bounded.push_back(static_cast<int>(j));
  }

  // Rows: Σ λ_k w_k + s·(weight; 0) = 0 (the contacts carry s × the weight), then each
  // bounded joint's torque Σ λ_k τ_jk within ±its effort limit. Columns: λ per edge, then s.
  const Eigen::Index cols = static_cast<Eigen::Index>(edges.size()) + 1;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(6 + static_cast<Eigen::Index>(bounded.size()), cols);
  for (size_t k = 0; k < edges.size(); ++k) {
    const Eigen::Index c = static_cast<Eigen::Index>(k);
    a.block<6, 1>(0, c) = edges[k];
    for (size_t b = 0; b < bounded.size(); ++b)
      a(6 + static_cast<Eigen::Index>(b), c) = edge_torques[k][bounded[b]];
  }
  a.block<3, 1>(0, cols - 1) = load.weight_O_N;
  GlpkProblem lp = make_glpk_problem(a);
  glp_prob* P = lp.get();
  glp_set_obj_dir(P, GLP_MAX);
  for (int k = 1; k < cols; ++k) glp_set_col_bnds(P, k, GLP_LO, 0.0, 0.0);
  glp_set_col_bnds(P, static_cast<int>(cols), GLP_DB, 0.0, max_margin);
  glp_set_obj_coef(P, static_cast<int>(cols), 1.0);
  for (int r = 1; r <= 6; ++r) glp_set_row_bnds(P, r, GLP_FX, 0.0, 0.0);
  for (size_t b = 0; b < bounded.size(); ++b) {
    const double e = effort_limits[bounded[b]];
    glp_set_row_bnds(P, 7 + static_cast<int>(b), GLP_DB, -e, e);
  }
  if (solve_glpk_problem(P) != GLP_OPT) return 0.0;
  return std::max(0.0, glp_get_obj_val(P));
}

}  // namespace cordgrasp
