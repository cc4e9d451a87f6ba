#include "cordgrasp/jobs/run_report_html.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cordgrasp/jobs/text_format.h"
#include "cordgrasp/jobs/trace_plot_svg.h"
#include "html_text.h"
#include "report_page.h"

namespace cordgrasp {
namespace {

std::string num(double v, const char* fmt = "%.3g") { return format_number(v, fmt); }

/// CSS class of an outcome's table cell: "held", "slipped", ..., "not-run".
std::string outcome_class(Outcome o) {
  std::string c = to_string(o);
  std::replace(c.begin(), c.end(), ' ', '-');
  return c;
}

/// The physics phases shown as table columns: every phase the results ran, settle aside.
std::vector<std::string> phase_columns(const SimDocument& sim) {
  std::vector<std::string> names;
  for (const SimResult& r : sim.results)
    for (const PhaseResult& p : r.phases)
      if (p.name != "settle" && std::find(names.begin(), names.end(), p.name) == names.end())
        names.push_back(p.name);
  return names;
}

/// The physics result of plan grasp k, or nullptr.
const SimResult* result_of(const RunReport& rep, int k) {
  if (!rep.sim) return nullptr;
  const std::vector<int>& idx = rep.sim->grasp_indices;
  const auto it = std::find(idx.begin(), idx.end(), k);
  return it == idx.end() ? nullptr : &rep.sim->results[static_cast<size_t>(it - idx.begin())];
}

void write_summary(const RunReport& rep, std::ostream& html) {
  const PlanDocument& plan = rep.plan;
  const int n = static_cast<int>(plan.grasps.size());
  html << "<p>";
  if (n == 0) {
    html << "<strong>No grasp</strong>"
         << (rep.interrupted.empty() ? "" : " before the interruption") << " ("
         << plan.stats.attempts << " attempts); report.md says why.</p>\n";
    return;
  }
  html << n << " force-closure grasp" << (n > 1 ? "s" : "") << " in " << num(plan.stats.total_s)
       << " s.";
  if (rep.sim) {
    int held = 0;
    for (const SimResult& r : rep.sim->results) held += r.held();
    html << " Physics (Bullet): <strong>" << held << " of " << rep.sim->results.size()
         << " held</strong> through " << html_escaped(to_string(rep.sim->tests)) << ".";
  } else {
    html << " Physics skipped.";
  }
  html << "</p>\n";
}

void write_verdict_table(const RunReport& rep, std::ostream& html) {
  const PlanDocument& plan = rep.plan;
  const std::vector<std::string> phases =
      rep.sim ? phase_columns(*rep.sim) : std::vector<std::string>{};
  const bool validated = plan.validation.has_value();
  const bool uncertain = rep.sim && !rep.sim->hold_probabilities.empty();
  html << "<table class=\"verdicts\">\n<tr><th>#</th><th>α [rad]</th><th>ε</th>";
  for (const std::string& p : phases) html << "<th>" << html_escaped(p) << "</th>";
  html << "<th>shift while closing [mm]</th><th>held</th>"
       << (validated ? "<th>held trials</th>" : "")
       << (uncertain ? "<th>P(held) [95 %]</th><th>failures go with</th>" : "")
       << "<th>pictures</th></tr>\n";
  for (size_t k = 0; k < plan.grasps.size(); ++k) {
    const Grasp& g = plan.grasps[k];
    const SimResult* r = result_of(rep, static_cast<int>(k));
    html << "<tr><td>" << k << "</td><td class=\"num\">" << num(g.alpha_rad, "%.3f")
         << "</td><td class=\"num\">" << num(g.epsilon, "%.4f") << "</td>";
    for (const std::string& name : phases) {
      const PhaseResult* p = r ? r->phase(name) : nullptr;
      const Outcome o = p ? p->outcome : Outcome::kNotRun;
      html << "<td class=\"" << outcome_class(o) << "\">" << to_string(o)
           << (p && !p->detail.empty() ? " (" + html_escaped(p->detail) + ")" : "") << "</td>";
    }
    const PhaseResult* close = r ? r->phase("close") : nullptr;
    html << "<td class=\"num\">" << (close ? num(1e3 * close->translation_m, "%.1f") : "–")
         << "</td><td class=\"" << (r ? (r->held() ? "held" : "dropped") : "not-run") << "\">"
         << (r ? (r->held() ? "yes" : "no") : "–") << "</td>";
    if (validated && k < plan.validation->grasps.size()) {
      const GraspValidation& v = plan.validation->grasps[k];
      html << "<td class=\"num\">" << v.held_trials << " / " << v.trials << "</td>";
    } else if (validated) {
      html << "<td>–</td>";
    }
    if (uncertain) {
      const HoldProbability* h = nullptr;
      for (size_t i = 0; i < rep.sim->grasp_indices.size(); ++i)
        if (rep.sim->grasp_indices[i] == static_cast<int>(k) &&
            i < rep.sim->hold_probabilities.size())
          h = &rep.sim->hold_probabilities[i];
      html << "<td class=\"num\">" << (h ? hold_probability_text(*h) : "–") << "</td><td>"
           << (h && h->sensitivity.most_associated ? to_string(*h->sensitivity.most_associated)
                                                    : "–")
           << "</td>";
    }
    html << "<td>"
         << (k < rep.pictures.size() ? "<a href=\"#grasp-" + std::to_string(k) + "\">grasp " +
                                           std::to_string(k) + "</a>"
                                     : "–")
         << "</td></tr>\n";
  }
  html << "</table>\n<p class=\"note\">α: skewness (docs/algorithm.md §9). ε: wrench-space "
          "quality (§8). A phase holds when the object moved and turned less than the "
          "thresholds in the hand and still touches it (docs/physics.md).</p>\n";
}

void write_figure(std::ostream& html, const std::string& src, const std::string& css,
                  const std::string& caption) {
  html << "<figure><img class=\"" << css << "\" src=\"" << html_escaped(src) << "\" alt=\""
       << html_escaped(caption) << "\"><figcaption>" << html_escaped(caption)
       << "</figcaption></figure>\n";
}

void write_grasp_section(const RunReport& rep, const ReportViewer& viewer, size_t k,
                         std::ostream& html) {
  const GraspPictures& p = rep.pictures[k];
  const SimResult* r = result_of(rep, static_cast<int>(k));
  html << "<section class=\"grasp\" id=\"grasp-" << k << "\">\n<h2>Grasp " << k;
  if (r) html << ": " << to_string(r->outcome);
  html << "</h2>\n";
  if (!p.planned.empty()) write_figure(html, p.planned, "picture", "planned: cords, contacts");
  const std::string model = k < viewer.models.size() ? html_escaped(viewer.models[k]) : "";
  if (!model.empty())
    html << "<figure><div class=\"viewer\" data-model=\"" << model << "\"></div>"
         << "<figcaption>3D: drag to turn, wheel to zoom, right-drag to move (<a href=\"" << model
         << ".glb\">" << model << ".glb</a>)</figcaption></figure>\n";
  html << "<br>\n";
  if (!p.animation.empty()) write_figure(html, p.animation, "animation", "the physics, animated");
  for (const std::string& f : p.snapshots) write_figure(html, f, "strip", "physics: " + f);
  const std::string plot = trace_plot_svg(p.trace, r);
  if (!plot.empty())
    html << "<figure>" << plot << "<figcaption>The object in the hand: shift of its centre of "
         << "mass and turn, against the planned pose in settle and close, against the pose "
         << "after closing from lift on.</figcaption></figure>\n";
  html << "</section>\n";
}

}  // namespace

std::string run_report_html(const RunReport& rep, const ReportViewer& viewer) {
  const PlanDocument& plan = rep.plan;
  const std::string title = "cordgrasp run: " + plan.object_name + " · " + plan.hand_name + " · " +
                            to_string(plan.planner) + " planner";
  std::ostringstream html;
  html << report_page_head(title);
  html << "<p class=\"note\">cordgrasp " << html_escaped(plan.cordgrasp_version)
       << ". Files: <a href=\"plan.json\">plan.json</a>"
       << (rep.sim ? ", <a href=\"sim.json\">sim.json</a>" : "")
       << ", <a href=\"report.md\">report.md</a> (inputs, parameters, every number).</p>\n";
  if (!rep.interrupted.empty())
    html << "<p class=\"warning\"><strong>Incomplete: interrupted by "
         << html_escaped(rep.interrupted) << " during " << html_escaped(rep.interrupted_at)
         << ".</strong> The files hold only what finished before.</p>\n";
  write_summary(rep, html);
  if (!plan.grasps.empty()) write_verdict_table(rep, html);
  if (!rep.sheet.empty()) write_figure(html, rep.sheet, "sheet", "all grasps");
  if (!viewer.unavailable.empty())
    html << "<p class=\"warning\">3D view unavailable: " << html_escaped(viewer.unavailable)
         << "</p>\n";
  for (size_t k = 0; k < rep.pictures.size(); ++k) write_grasp_section(rep, viewer, k, html);

  html << "<h2>Timings</h2>\n<table>\n<tr><th>stage</th><th>wall [s]</th></tr>\n"
       << "<tr><td>planning</td><td class=\"num\">" << num(rep.plan_wall_s) << "</td></tr>\n";
  if (rep.sim)
    html << "<tr><td>physics</td><td class=\"num\">" << num(rep.sim_wall_s) << "</td></tr>\n";
  if (!rep.pictures.empty())
    html << "<tr><td>rendering</td><td class=\"num\">" << num(rep.render_wall_s) << "</td></tr>\n";
  html << "</table>\n";
  const bool views = std::any_of(viewer.models.begin(), viewer.models.end(),
                                 [](const std::string& m) { return !m.empty(); });
  if (views && !viewer.scripts_dir.empty()) {
    const std::string dir = html_escaped(viewer.scripts_dir);
    html << "<p class=\"note\">3D view: three.js from Debian's libjs-three, MIT licence "
         << "(<a href=\"" << dir << "/copyright\">" << dir << "/copyright</a>).</p>\n"
         << "<script src=\"" << dir << "/three.min.js\"></script>\n<script src=\"" << dir
         << "/GLTFLoader.js\"></script>\n<script src=\"" << dir
         << "/OrbitControls.js\"></script>\n";
    for (const std::string& m : viewer.models)
      if (!m.empty()) html << "<script src=\"" << html_escaped(m) << ".glb.js\"></script>\n";
  }
  html << report_page_tail();
  return html.str();
}

}  // namespace cordgrasp
