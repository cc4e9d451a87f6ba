#include "plan_internal.h"

#include <cmath>

#include "cordgrasp/core/candidate_measures.h"
#include "cordgrasp/core/kinematics.h"
#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/core/skewness.h"

namespace cordgrasp::internal {

bool touched_from_inside(const WindingNumberTree& solid, const std::vector<Contact>& contacts) {
  for (const Contact& c : contacts)
    if (std::abs(winding_number(solid, c.p_O + kInsideProbeOffsetM * c.n_O)) >= 0.5) return true;
  return false;
}

PlanContext make_plan_context(const Mesh& mesh, const HandModel& hand, HandObjectCollider& collider,
                              const PlanParams& params, PlanStats& stats) {
  const auto start = std::chrono::steady_clock::now();
  PlanContext ctx = cordgrasp::make_plan_context(mesh, hand, collider, params);
  stats.setup_s += seconds_since(start);
  return ctx;
}

bool attempt_grasp(const HandModel& hand, HandObjectCollider& collider, const PlanContext& ctx,
                   const PlanParams& params, const Eigen::Isometry3d& X_OG_start,
                   double approach_travel_m, PlanStats& stats, Grasp& grasp) {
  ++stats.attempts;
  const auto t_finger = std::chrono::steady_clock::now();
  const FingerResult fr =
      run_finger_stage(hand, ctx.setup, collider, X_OG_start, approach_travel_m, params.finger);
  const double finger_s = seconds_since(t_finger);
  stats.finger_s += finger_s;
  switch (fr.status) {
    case FingerStatus::kOk:
      break;
    case FingerStatus::kNoContact:
      ++stats.no_contact;
      return false;
    case FingerStatus::kOneContact:
      ++stats.one_contact;
      return false;
    case FingerStatus::kCannotRetreat:
      ++stats.cannot_retreat;
      return false;
  }
  if (ctx.solid && touched_from_inside(*ctx.solid, fr.contacts)) {
    ++stats.inside_object;
    return false;
  }
  const auto t_quality = std::chrono::steady_clock::now();
  const GraspQuality quality =
      evaluate_grasp_quality(fr.contacts, ctx.wrench_object, params.quality);
  const double quality_s = seconds_since(t_quality);
  stats.quality_s += quality_s;
  if (!quality.force_closure) {
    ++stats.not_force_closure;
    return false;
  }
  const CandidateMeasures measures =
      candidate_measures(fr.contacts, ctx.setup, ctx.com_O, ctx.radius_m);
  grasp = Grasp{};
  grasp.X_OB = fr.X_OB;
  grasp.X_OG = fr.X_OG;
  grasp.q = fr.q;
  grasp.q_preshape = fr.q_preshape;
  grasp.contacts = fr.contacts;
  grasp.force_closure = true;
  grasp.epsilon = quality.epsilon;
  grasp.measures = measures;
  grasp.alpha_approach_rad =
      skewness_alpha_rad(fr.X_OG.linear().col(2), ctx.principal_axis_O);
  grasp.alpha_rad = grasp.alpha_approach_rad;
  if (hand.palm_normal) {
    const auto X_OL = link_poses(hand, fr.q, fr.X_OB);
    const Eigen::Vector3d n_O = X_OL[hand.palm_normal->link].linear() * hand.palm_normal->n_L;
    grasp.alpha_rad = skewness_alpha_rad(n_O, ctx.principal_axis_O);
  }
  grasp.times.finger_s = finger_s;
  grasp.times.quality_s = quality_s;
  ++stats.force_closure;
  return true;
}

}  // namespace cordgrasp::internal
