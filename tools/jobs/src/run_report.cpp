#include "cordgrasp/jobs/run_report.h"

#include "cordgrasp/jobs/text_format.h"
#include "cordgrasp/jobs/validated_plan_job.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace cordgrasp {
namespace {

std::string num(double v, const char* fmt = "%.3g") { return format_number(v, fmt); }

std::string outcome_text(const SimResult& r) {
  std::string text = to_string(r.outcome);
  for (const PhaseResult& p : r.phases)
    if (p.outcome != Outcome::kHeld && p.outcome != Outcome::kNotRun) {
      text += " in " + p.name + (p.detail.empty() ? "" : " (" + p.detail + ")");
      break;
    }
  if (r.preshape_overlap) text += "; the preshape hand overlaps the collision shape";
  return text;
}

}  // namespace

std::string run_report_markdown(const RunReport& rep) {
  const PlanDocument& plan = rep.plan;
  const PlanStats& s = plan.stats;
  std::ostringstream md;
  md << "# cordgrasp run: " << plan.object_name << " · " << plan.hand_name << " · "
     << to_string(plan.planner) << " planner\n\n";
  md << "cordgrasp " << plan.cordgrasp_version << ". Files: `plan.json` (grasps), "
     << (rep.sim ? "`sim.json` (physics), " : "") << "PNG pictures, this report.\n\n";
  if (!rep.interrupted.empty())
    md << "**Incomplete: interrupted by " << rep.interrupted << " during " << rep.interrupted_at
       << ".** The files hold only what finished before; later stages did not run.\n\n";

  md << "## Inputs\n\n";
  md << "- Object: `" << plan.object_path << "` (" << plan.object_triangles << " triangles, units "
     << plan.object_units << ", scale " << format_number(plan.object_scale) << ")\n";
  md << "- Hand: " << plan.hand_name << " (`" << plan.hand_path << "`)\n";
  md << "- Planner: " << to_string(plan.planner) << ", up to "
     << plan.params.grasps << " grasps, at most " << plan.params.max_attempts
     << " attempts, time limit " << num(plan.params.time_limit_s) << " s, seed " << plan.params.seed << ", μ " << num(plan.params.quality.contact.mu)
     << ", soft-finger radius " << num(plan.params.quality.contact.soft_finger_radius_m)
     << " m, quality " << to_string(plan.params.quality.mode) << "\n";
  if (rep.sim)
    md << "- Physics (Bullet): tests " << to_string(rep.sim->tests) << ", time step "
       << num(rep.sim->params.time_step_s, "%.5f") << " s, object mass "
       << (rep.sim->results.empty() ? std::string("–")
                                    : num(rep.sim->results.front().object.mass_kg) + " kg")
       << "\n";
  else
    md << "- Physics: skipped (`--tests none`)\n";
  if (plan.validation) {
    const ValidationParams& v = plan.validation->params;
    if (is_none(v.uncertainty))
      md << "- Validated planning: accepted when held in ≥ " << v.min_held << " of "
         << v.trials << " trials" << (v.require_held_as_planned ? ", the first as planned" : "");
    else
      md << "- Validated planning: accepted when held as planned and P(held) under uncertainty "
            "lies above "
         << num(v.min_hold_probability, "%.2f") << " (Wilson 95 %, at most " << v.max_draws
         << " draws, then again on other draws), ranked by P(held)";
    md << " ("
       << v.tests << ", " << to_string(v.protocol) << " protocol), squeeze shift "
       << "limit " << num(1e3 * v.squeeze_shift_limit_m, "%.0f") << " mm, budget "
       << num(v.budget_s) << " s\n";
  }
  const DiversityParams& d = plan.params.diversity;
  md << "- Grasps differ pairwise by ≥ " << num(1e3 * d.min_gcp_distance_m, "%.0f") << " mm ("
     << num(100.0 * d.min_gcp_distance_per_radius, "%.0f")
     << " % of the object's bounding radius, if more) or ≥ " << num(d.min_hand_turn_deg, "%.0f")
     << "° of hand turn\n";
  md << "\n## Result\n\n";
  if (s.timed_out)
    md << "**Machine-dependent result:** the " << num(plan.params.time_limit_s)
       << " s time limit stopped the planner before its attempt budget, so the same seed may "
          "give other grasps on a faster or slower machine.\n\n";
  const int n = static_cast<int>(plan.grasps.size());
  if (plan.validation)
    md << "Validated planning: " << validation_stats_line(plan.validation->stats, plan.params.grasps)
       << ".\n\n";
  if (n == 0 && !rep.interrupted.empty()) {
    md << "**No grasp** found before the interruption (" << s.attempts << " attempts).\n";
    return md.str();
  }
  if (n == 0 && plan.validation && plan.validation->stats.force_closure > 0) {
    md << "**No grasp held** in physics.\n";
    return md.str();
  }
  if (n == 0) {
    md << "**No force-closure grasp found** in " << num(s.total_s) << " s (" << s.attempts
       << " attempts: " << s.not_force_closure << " not force closure, " << s.one_contact
       << " with one contact, " << s.no_contact << " without contact, " << s.cannot_retreat
       << " could not retreat, " << s.inside_object << " touched the object from inside"
       << (s.timed_out ? "; time limit reached" : "") << ").\n";
    return md.str();
  }
  md << n << " force-closure grasp" << (n > 1 ? "s" : "") << " in " << num(s.total_s)
     << " s; the first after " << (s.first_force_closure_s ? num(*s.first_force_closure_s) : "–")
     << " s (" << s.attempts << " finger-stage attempts";
  if (plan.planner == PlannerKind::kCord) md << ", " << s.regions_processed << " of " << s.regions << " regions";
  md << ").";
  if (rep.sim) {
    int held = 0;
    for (const SimResult& r : rep.sim->results) held += r.held();
    md << " Physics: **" << held << " of " << rep.sim->results.size() << " held** through "
       << to_string(rep.sim->tests) << ".";
  }
  const bool validated = plan.validation.has_value();
  const bool uncertain = rep.sim && !rep.sim->hold_probabilities.empty();
  md << "\n\n| # | α [rad] | ε | χ [mm²] | region | contacts | physics | max penetration [mm] |"
        " closing: shift [mm], turn [°] | planned contacts to simulated, max [mm] |"
     << (validated ? " held trials | squeeze shift [mm] |" : "")
     << (uncertain ? " P(held) [95 %] | draws | failures go with |" : "") << "\n"
     << "|---|---|---|---|---|---|---|---|---|---|" << (validated ? "---|---|" : "")
     << (uncertain ? "---|---|---|" : "") << "\n";
  for (int k = 0; k < n; ++k) {
    const Grasp& g = plan.grasps[static_cast<size_t>(k)];
    md << "| " << k << " | " << num(g.alpha_rad, "%.3f") << " | " << num(g.epsilon, "%.4f")
       << " | " << (g.chi_m2 ? num(*g.chi_m2 * 1e6, "%.1f") : "–") << " | "
       << (g.region_rank ? std::to_string(*g.region_rank) : "–") << " | " << g.contacts.size()
       << " | ";
    const SimResult* r = nullptr;
    const HoldProbability* hp = nullptr;
    if (rep.sim)
      for (size_t i = 0; i < rep.sim->grasp_indices.size(); ++i)
        if (rep.sim->grasp_indices[i] == k) {
          r = &rep.sim->results[i];
          if (i < rep.sim->hold_probabilities.size()) hp = &rep.sim->hold_probabilities[i];
        }
    if (r) {
      double pen = 0.0;
      for (const PhaseResult& p : r->phases) pen = std::max(pen, p.max_penetration_m);
      md << outcome_text(*r) << " | " << num(pen * 1e3, "%.2f") << " | ";
      if (const PhaseResult* close = r->phase("close"))
        md << num(close->translation_m * 1e3, "%.1f") << ", "
           << num(close->rotation_rad * 180.0 / M_PI, "%.1f");
      else
        md << "–";
      double farthest = r->planned_contact_offsets_m.empty() ? std::nan("") : 0.0;
      for (const double d : r->planned_contact_offsets_m)
        farthest = std::isfinite(d) ? std::max(farthest, d) : d;  // NaN: touches nothing
      md << " | " << (std::isfinite(farthest) ? num(farthest * 1e3, "%.1f") : "–") << " |";
    } else {
      md << "– | – | – | – |";
    }
    if (validated) {
      const GraspValidation& gv = plan.validation->grasps[static_cast<size_t>(k)];
      md << " " << gv.held_trials << " / " << gv.trials << " | "
         << num(1e3 * gv.squeeze_shift_m, "%.1f") << " |";
    }
    if (uncertain) {
      if (hp)
        md << " " << hold_probability_text(*hp) << " | " << hp->draws.size() << " | "
           << (hp->sensitivity.most_associated ? to_string(*hp->sensitivity.most_associated)
                                               : "–")
           << " |";
      else
        md << " – | – | – |";
    }
    md << "\n";
  }
  if (uncertain)
    md << "\nP(held): the share of draws of hand pose, friction, mass, centre of mass and grip "
          "force (docs/physics.md §3b) in which the grasp held, with its Wilson 95 % interval; "
          "drawn until the interval lies above or below "
       << num(rep.sim->hold_test.min_hold_probability, "%.2f") << " or "
       << rep.sim->hold_test.max_draws
       << " draws are spent (`cordgrasp validate --plan plan.json --uncertainty realistic` "
          "draws up to "
       << HoldProbabilityParams{}.max_draws
       << "). Failures go with: the factor whose draws differ most between failed "
          "and held "
          "draws.\n";
  md << "\nα: skewness (0 = the hand's axis on the object's principal axis; "
        "docs/algorithm.md §9). ε: wrench-space quality (docs/algorithm.md §8). χ: XOR measure "
        "of the grasp region (docs/algorithm.md §6).\n";

  md << "\n## Timings\n\n| stage | wall [s] |\n|---|---|\n";
  if (plan.planner == PlannerKind::kCord) md << "| cord exploration | " << num(s.exploration_s) << " |\n";
  md << "| finger stage | " << num(s.finger_s) << " |\n"
     << "| grasp quality | " << num(s.quality_s) << " |\n"
     << "| planning (total) | " << num(rep.plan_wall_s) << " |\n";
  if (rep.sim) md << "| physics | " << num(rep.sim_wall_s) << " |\n";
  if (!rep.pictures.empty()) md << "| rendering | " << num(rep.render_wall_s) << " |\n";

  if (!rep.pictures.empty() || !rep.sheet.empty()) {
    md << "\n## Pictures\n\n";
    if (!rep.sheet.empty()) md << "All grasps: ![grasps](" << rep.sheet << ")\n\n";
    for (size_t k = 0; k < rep.pictures.size(); ++k) {
      const GraspPictures& p = rep.pictures[k];
      md << "### Grasp " << k << "\n\n";
      if (!p.planned.empty()) md << "Planned: ![grasp " << k << "](" << p.planned << ")\n\n";
      if (!p.snapshots.empty()) {
        md << "Physics:";
        for (const std::string& f : p.snapshots) md << " ![" << f << "](" << f << ")";
        md << "\n\n";
      }
    }
  }
  return md.str();
}

}  // namespace cordgrasp
