#include "glpk_problem.h"

#include <cmath>
#include <vector>

namespace cordgrasp {
namespace {

// Coefficients below this are round-off of zero (unit forces, lever arms in metres).
constexpr double kNegligible = 1e-12;

}  // namespace

GlpkProblem make_glpk_problem(const Eigen::MatrixXd& a) {
  GlpkProblem lp(glp_create_prob());
  glp_add_rows(lp.get(), static_cast<int>(a.rows()));
  glp_add_cols(lp.get(), static_cast<int>(a.cols()));
  std::vector<int> ia{0}, ja{0};  // GLPK's arrays start at index 1
  std::vector<double> ar{0.0};
  for (Eigen::Index c = 0; c < a.cols(); ++c)
    for (Eigen::Index r = 0; r < a.rows(); ++r)
      if (std::abs(a(r, c)) >= kNegligible) {
        ia.push_back(static_cast<int>(r) + 1);
        ja.push_back(static_cast<int>(c) + 1);
        ar.push_back(a(r, c));
      }
  glp_load_matrix(lp.get(), static_cast<int>(ia.size()) - 1, ia.data(), ja.data(), ar.data());
  return lp;
}

int solve_glpk_problem(glp_prob* problem) {
  glp_term_out(GLP_OFF);  // the scaling reports on the terminal whatever msg_lev says
  glp_scale_prob(problem, GLP_SF_AUTO);
  glp_smcp parm;
  glp_init_smcp(&parm);
  parm.msg_lev = GLP_MSG_OFF;
  return glp_simplex(problem, &parm) == 0 ? glp_get_status(problem) : GLP_UNDEF;
}

}  // namespace cordgrasp
