#pragma once
// core-internal: linear programs on GLPK (weight_margin, the force-closure test of
// evaluate_grasp_quality).
#include <glpk.h>

#include <Eigen/Core>
#include <memory>

namespace cordgrasp {

struct GlpkDeleter {
  void operator()(glp_prob* p) const { glp_delete_prob(p); }
};
using GlpkProblem = std::unique_ptr<glp_prob, GlpkDeleter>;

/// A problem with a.rows() rows and a.cols() columns whose constraint matrix is `a`; entries
/// below 1e-12 in magnitude (round-off of zero, which would ruin the simplex's scaling) are
/// left out. Bounds and objective are the caller's.
GlpkProblem make_glpk_problem(const Eigen::MatrixXd& a);

/// Scales the problem and runs GLPK's simplex (no presolver, no output): the status of the
/// solution it ends with (GLP_OPT, GLP_NOFEAS, ...), GLP_UNDEF when the simplex failed.
int solve_glpk_problem(glp_prob* problem);

}  // namespace cordgrasp
