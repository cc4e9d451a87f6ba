#include "cordgrasp/jobs/bench_report_html.h"

#include <algorithm>
#include <sstream>

#include "cordgrasp/jobs/first_fc_cdf_svg.h"
#include "html_text.h"
#include "report_page.h"

namespace cordgrasp {
namespace {

/// A summary table; the first `key_columns` cells of a row name it, the rest are numbers.
void write_table(const BenchSummaryTable& table, size_t key_columns, const std::string& css,
                 std::ostream& html) {
  html << "<table class=\"" << css << "\">\n<tr>";
  for (const std::string& c : table.columns) html << "<th>" << html_escaped(c) << "</th>";
  html << "</tr>\n";
  for (const auto& row : table.rows) {
    html << "<tr>";
    for (size_t i = 0; i < row.size(); ++i)
      html << (i < key_columns ? "<td>" : "<td class=\"num\">") << html_escaped(row[i])
           << "</td>";
    html << "</tr>\n";
  }
  html << "</table>\n";
}

/// Per hand × planner (in attempt order): a figure with the plot of its first FC times.
void write_first_fc_plots(const std::vector<BenchRow>& rows, std::ostream& html) {
  std::vector<std::pair<std::string, std::string>> keys;
  for (const BenchRow& r : rows)
    if (std::find(keys.begin(), keys.end(), std::pair{r.hand, r.planner}) == keys.end())
      keys.emplace_back(r.hand, r.planner);
  for (const auto& [hand, planner] : keys) {
    std::vector<double> first_fc_s;
    int attempts = 0;
    for (const BenchRow& r : rows) {
      if (r.hand != hand || r.planner != planner) continue;
      ++attempts;
      if (r.status == "ok" && r.first_fc_s) first_fc_s.push_back(*r.first_fc_s);
    }
    const std::string caption = hand + " · " + planner + ": " +
                                std::to_string(first_fc_s.size()) + " of " +
                                std::to_string(attempts) + " attempts found a grasp";
    html << "<figure class=\"plot\">" << first_fc_cdf_svg(first_fc_s, attempts)
         << "<figcaption>" << html_escaped(caption) << "</figcaption></figure>\n";
  }
}

}  // namespace

std::string bench_report_html(const std::vector<BenchRow>& rows, const BenchSummaryInfo& info) {
  std::ostringstream html;
  html << report_page_head("cordgrasp bench summary");
  html << "<p class=\"note\">Files: <a href=\"results.csv\">results.csv</a> (one row per "
          "attempt), <a href=\"summary.md\">summary.md</a> (these tables), "
          "<a href=\"bench.json\">bench.json</a> (the parameters).</p>\n";
  if (!info.interrupted.empty())
    html << "<p class=\"warning\"><strong>Incomplete: interrupted by "
         << html_escaped(info.interrupted) << " after " << rows.size() << " of "
         << info.attempts_asked << " attempts.</strong> The attempts in flight were abandoned "
         << "and the rest did not run.</p>\n";
  const auto timed_out =
      std::count_if(rows.begin(), rows.end(), [](const BenchRow& r) { return r.timed_out; });
  html << "<ul>\n<li>command: <code>" << html_escaped(info.command) << "</code>";
  if (!info.merged_from.empty()) {
    html << "<ul>";
    for (const std::string& c : info.merged_from)
      html << "<li>merged from: <code>" << html_escaped(c) << "</code></li>";
    html << "</ul>";
  }
  html << "</li>\n"
       << "<li>machine: " << html_escaped(info.machine) << "</li>\n"
       << "<li>attempts: " << rows.size() << " of " << info.attempts_total
       << (info.shard.empty() ? "" : " (shard " + html_escaped(info.shard) + ")") << "</li>\n"
       << "<li>physics tests on each attempt's first grasp: "
       << html_escaped(info.tests.empty() ? "none" : info.tests) << "</li>\n"
       << "<li>attempts stopped by the --time-limit safety net (machine-dependent): "
       << timed_out << "</li>\n</ul>\n";

  const BenchSummaryTables tables = bench_summary_tables(rows);
  html << "<h2>Totals per hand and planner (all objects)</h2>\n";
  write_table(tables.totals, 2, "totals", html);
  write_first_fc_plots(rows, html);
  html << "<p class=\"note\">Times are wall-clock seconds. α: skewness (docs/algorithm.md §9; "
          "of the palm normal, α approach of the GCP z axis) and ε of the first force-closure "
          "grasp; first FC, α and ε over the attempts that found a grasp; sim held: first "
          "grasps that held through every test / first grasps simulated; P(held) median: of the "
          "first grasps' P(held) under --uncertainty (docs/physics.md §3b). The plots: the share "
          "of all attempts that had found a force-closure grasp by a time; the dashed line is "
          "the share that found one at all.</p>\n";
  html << "<h2>Per object, hand and planner</h2>\n";
  write_table(tables.per_object, 3, "per-object", html);

  std::vector<const BenchRow*> errors;
  for (const BenchRow& r : rows)
    if (r.status == "error") errors.push_back(&r);
  if (!errors.empty()) {
    html << "<h2>Errors</h2>\n<ul>\n";
    for (const BenchRow* r : errors)
      html << "<li>attempt " << r->attempt << " (" << html_escaped(r->object) << ", "
           << html_escaped(r->hand) << ", " << html_escaped(r->planner) << ", repeat "
           << r->repeat << "): " << html_escaped(r->error) << "</li>\n";
    html << "</ul>\n";
  }
  if (info.sheets.empty() && !info.merged_from.empty())
    html << "<p class=\"note\">Contact sheets: in the shard folders (merge does not copy "
            "them).</p>\n";
  if (!info.sheets.empty()) {
    html << "<h2>Contact sheets</h2>\n<p class=\"note\">Per object, for each hand and planner, "
            "the attempt whose first grasp has the highest ε.</p>\n";
    for (const std::string& s : info.sheets)
      html << "<figure><img class=\"sheet\" src=\"" << html_escaped(s) << "\" alt=\""
           << html_escaped(s) << "\"><figcaption><a href=\"" << html_escaped(s) << "\">"
           << html_escaped(s) << "</a></figcaption></figure>\n";
  }
  html << report_page_tail();
  return html.str();
}

}  // namespace cordgrasp
