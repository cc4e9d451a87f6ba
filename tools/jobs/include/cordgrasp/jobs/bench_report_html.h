#pragma once
// report.html of `cordgrasp bench` and `cordgrasp merge`: summary.md's tables, a plot of the
// time to the first force-closure grasp per hand and planner, and the contact sheets, readable
// offline from the output folder.
#include <string>
#include <vector>

#include "cordgrasp/jobs/bench_job.h"

namespace cordgrasp {

/// HTML text of a bench's report.html: what the bench ran (command, machine, attempts, tests),
/// the totals per hand and planner (bench_summary_tables) each with a plot of the share of
/// attempts that had found a force-closure grasp against time (first_fc_cdf_svg), the table
/// per object, hand and planner, the error rows, and the contact sheets `info.sheets` as
/// images. It links results.csv, summary.md and bench.json beside it and refers to no other
/// file and no external URL; it runs the same self-test as run_report_html.
std::string bench_report_html(const std::vector<BenchRow>& rows, const BenchSummaryInfo& info);

}  // namespace cordgrasp
