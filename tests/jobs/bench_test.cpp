// `cordgrasp bench` / `cordgrasp merge` and their library (bench_job.h): attempt list, seeds,
// shards, results.csv, merging, parallel runs, error rows.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "cordgrasp/jobs/bench_job.h"
#include "cordgrasp/jobs/bench_report_html.h"
#include "cordgrasp/jobs/first_fc_cdf_svg.h"
#include "cordgrasp/core/error.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

namespace fs = std::filesystem;

std::string quoted(const std::string& path) { return "\"" + path + "\""; }

std::string temp_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() /
                       ("cordgrasp_bench_test_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

std::string shipped_object(const std::string& name) {
  return test::source_dir() + "/assets/objects/" + name + ".obj";
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<BenchRow> read_rows(const std::string& dir) {
  return parse_bench_csv(read_file(dir + "/results.csv"), dir + "/results.csv");
}

// Cells of every row with the wall-clock columns blanked (they differ between runs).
std::vector<std::vector<std::string>> rows_without_timings(const std::vector<BenchRow>& rows) {
  const auto& columns = bench_csv_columns();
  const auto& timing = bench_timing_columns();
  std::vector<std::vector<std::string>> out;
  for (const BenchRow& r : rows) {
    std::vector<std::string> cells = bench_row_cells(r);
    for (size_t i = 0; i < columns.size(); ++i)
      if (std::find(timing.begin(), timing.end(), columns[i]) != timing.end()) cells[i].clear();
    out.push_back(cells);
  }
  return out;
}

// What is wrong with the links of report.html in `dir`: every href and src must name a file
// in the folder that exists (relative, no URL); results.csv, summary.md and bench.json at least.
std::vector<std::string> report_link_problems(const std::string& dir) {
  const std::string html = read_file(dir + "/report.html");
  if (html.empty()) return {dir + "/report.html is missing or empty"};
  std::vector<std::string> problems;
  for (const char* scheme : {"http://", "https://"})
    if (html.find(scheme) != std::string::npos) problems.push_back(std::string("URL ") + scheme);
  const std::regex link(R"re((?:href|src)="([^"]*)")re");
  std::set<std::string> targets;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), link);
       it != std::sregex_iterator(); ++it) {
    const std::string target = (*it)[1];
    targets.insert(target);
    if (target.empty() || target[0] == '/' || target.find(':') != std::string::npos ||
        target.find("..") != std::string::npos)
      problems.push_back("not a file in the folder: " + target);
    else if (!fs::is_regular_file(fs::path(dir) / target))
      problems.push_back("links a missing file: " + target);
  }
  for (const char* file : {"results.csv", "summary.md", "bench.json"})
    if (!targets.count(file)) problems.push_back(std::string("does not link ") + file);
  return problems;
}

BenchParams two_object_params() {
  BenchParams p;
  p.objects = {"a.obj", "b.obj"};
  p.hands = {"h1", "h2"};
  p.planners = {PlannerKind::kCord, PlannerKind::kGeneric};
  p.repeats = 3;
  p.seed = 7;
  return p;
}

TEST(BenchAttempts, AreObjectMajorWithSeedPerRepeat) {
  const auto attempts = bench_attempts(two_object_params());
  ASSERT_EQ(attempts.size(), 2u * 2u * 2u * 3u);
  for (size_t i = 0; i < attempts.size(); ++i) {
    EXPECT_EQ(attempts[i].index, static_cast<int>(i));
    EXPECT_EQ(attempts[i].seed, 7u + static_cast<unsigned>(attempts[i].repeat));
  }
  EXPECT_EQ(attempts[0].object_path, "a.obj");
  EXPECT_EQ(attempts[11].object_path, "a.obj");
  EXPECT_EQ(attempts[12].object_path, "b.obj");
  EXPECT_EQ(attempts[3].planner, PlannerKind::kGeneric);
  EXPECT_EQ(attempts[6].hand, "h2");
  EXPECT_EQ(attempts[2].repeat, 2);
}

TEST(BenchAttempts, ShardsPartitionTheAttempts) {
  const auto attempts = bench_attempts(two_object_params());
  constexpr int kShards = 5;
  std::multiset<int> seen;
  for (int k = 1; k <= kShards; ++k)
    for (const auto& a : shard_attempts(attempts, k, kShards)) {
      EXPECT_EQ(a.index % kShards, k - 1);
      seen.insert(a.index);
    }
  ASSERT_EQ(seen.size(), attempts.size());
  for (size_t i = 0; i < attempts.size(); ++i) EXPECT_EQ(seen.count(static_cast<int>(i)), 1u);
}

TEST(BenchAttempts, ParseShardAcceptsOnlyKOverN) {
  EXPECT_EQ(parse_shard("2/3"), std::make_pair(2, 3));
  EXPECT_EQ(parse_shard("1/1"), std::make_pair(1, 1));
  for (const char* bad : {"0/3", "4/3", "3", "a/b", "1/0", "1/2x", ""})
    EXPECT_THROW(parse_shard(bad), InputError) << bad;
}

TEST(BenchAttempts, ObjectDirectoryExpandsToSortedMeshFiles) {
  const std::string dir = temp_dir("expand");
  for (const char* name : {"b.obj", "a.STL", "notes.txt"}) std::ofstream(dir + "/" + name) << "x";
  const auto files = expand_object_args({dir});
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(fs::path(files[0]).filename(), "a.STL");
  EXPECT_EQ(fs::path(files[1]).filename(), "b.obj");
  EXPECT_THROW(expand_object_args({dir + "/missing"}), InputError);
  fs::remove_all(dir);
}

TEST(BenchCsv, RowsRoundTripIncludingQuotedErrors) {
  BenchRow ok;
  ok.attempt = 3;
  ok.object = "box";
  ok.object_path = "/x/box.obj";
  ok.hand = "cordgrasp_sah";
  ok.planner = "cord";
  ok.repeat = 1;
  ok.seed = 42;
  ok.status = "ok";
  ok.first_fc_s = 0.25;
  ok.total_s = 0.5;
  ok.regions = 20;
  ok.regions_processed = 2;
  ok.finger_attempts = 3;
  ok.grasps = 1;
  ok.epsilon = 0.123456789;
  ok.alpha_rad = 0.1;
  ok.chi_m2 = 1.5e-4;
  ok.region_rank = 1;
  ok.sim_lift = "held";
  ok.sim_shake = "slipped";
  ok.sim_gravity6 = "not_run";
  ok.sim_outcome = "slipped";
  ok.sim_wall_s = 1.5;
  ok.validated_accepted = 3;
  ok.validated_candidates = 9;
  ok.validated_first_accepted_cpu_s = 2.5;
  ok.hold_p = 0.75;
  ok.hold_low = 0.5;
  ok.hold_high = 0.9;
  ok.hold_draws = 8;
  ok.hold_cpu_s = 1.25;
  BenchRow bad;
  bad.attempt = 4;
  bad.object = "bad";
  bad.status = "error";
  bad.error = "load_mesh: 'a, \"b\"':\nno triangles";
  const std::string text = bench_csv({ok, bad});
  EXPECT_EQ(text.substr(0, text.find('\n')),
            "attempt,object,object_path,hand,planner,repeat,seed,status,error,first_fc_s,"
            "exploration_s,finger_s,quality_s,total_s,regions,regions_processed,"
            "finger_attempts,grasps,timed_out,epsilon,alpha_rad,alpha_approach_rad,chi_m2,"
            "region_rank,sim_lift,sim_shake,sim_gravity6,sim_outcome,sim_wall_s,object_scale,"
            "validated_accepted,validated_candidates,validated_simulated,"
            "validated_rejected_early,validated_held_as_planned,validated_first_accepted_cpu_s,"
            "validated_cpu_s,hold_p,hold_low,hold_high,hold_draws,hold_cpu_s");
  const auto rows = parse_bench_csv(text, "test");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(bench_row_cells(rows[0]), bench_row_cells(ok));
  EXPECT_EQ(bench_row_cells(rows[1]), bench_row_cells(bad));
  EXPECT_EQ(rows[1].error, bad.error);
  EXPECT_FALSE(rows[1].first_fc_s.has_value());
  EXPECT_FALSE(rows[1].region_rank.has_value());
  EXPECT_EQ(rows[0].hold_draws, 8);
  EXPECT_FALSE(rows[1].hold_p.has_value());
}

TEST(BenchCsv, ParseRejectsAnotherHeaderAndShortRows) {
  EXPECT_THROW(parse_bench_csv("a,b\n1,2\n", "x"), InputError);
  std::string text = bench_csv({});
  text += "1,box\n";
  EXPECT_THROW(parse_bench_csv(text, "x"), InputError);
}

TEST(BenchCsv, AFileWithoutTheNewerColumnsReadsWithTheirDefaults) {
  // results.csv from before alpha_approach_rad, object_scale, validated_* and hold_*
  // (28 columns).
  BenchRow row;
  row.attempt = 2;
  row.object = "mug";
  row.status = "ok";
  row.alpha_rad = 0.25;
  row.alpha_approach_rad = 0.5;
  row.object_scale = 2.0;
  row.validated_accepted = 3;
  row.hold_p = 0.5;
  const std::vector<std::string> names = bench_csv_columns(), cells = bench_row_cells(row);
  std::string header, line;
  for (size_t i = 0; i < names.size(); ++i) {
    if (names[i] == "alpha_approach_rad" || names[i] == "object_scale" ||
        names[i].rfind("validated_", 0) == 0 || names[i].rfind("hold_", 0) == 0)
      continue;
    header += (header.empty() ? "" : ",") + names[i];
    line += (line.empty() ? "" : ",") + cells[i];
  }
  const auto rows = parse_bench_csv(header + "\n" + line + "\n", "old.csv");
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].attempt, 2);
  EXPECT_EQ(rows[0].alpha_rad, 0.25);
  EXPECT_FALSE(rows[0].alpha_approach_rad.has_value());
  EXPECT_EQ(rows[0].object_scale, 1.0);
  EXPECT_FALSE(rows[0].validated_accepted.has_value());
  EXPECT_FALSE(rows[0].hold_p.has_value());
  // A required column missing, or an unknown one, is refused.
  EXPECT_THROW(parse_bench_csv(header.substr(header.find(',') + 1) + "\n", "x"), InputError);
  EXPECT_THROW(parse_bench_csv(header + ",extra\n", "x"), InputError);
}

TEST(BenchMerge, SortsByAttemptAndRejectsDuplicates) {
  BenchRow a, b, c;
  a.attempt = 0;
  b.attempt = 1;
  c.attempt = 2;
  const auto merged = merge_bench_rows({{b}, {c, a}});
  ASSERT_EQ(merged.size(), 3u);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(merged[i].attempt, i);
  EXPECT_THROW(merge_bench_rows({{a, b}, {b}}), InputError);
}

TEST(BenchSummary, CountsSuccessAndHoldRatePerGroup) {
  std::vector<BenchRow> rows(3);
  for (int i = 0; i < 3; ++i) {
    rows[i].attempt = i;
    rows[i].object = "box";
    rows[i].object_path = "box.obj";
    rows[i].hand = "h";
    rows[i].planner = "cord";
  }
  rows[0].status = "ok";
  rows[0].first_fc_s = 1.0;
  rows[0].alpha_rad = 0.2;
  rows[0].sim_outcome = "held";
  rows[1].status = "ok";
  rows[1].first_fc_s = 3.0;
  rows[1].alpha_rad = 0.4;
  rows[1].sim_outcome = "dropped";
  rows[0].hold_p = 0.9;
  rows[1].hold_p = 0.4;
  rows[2].status = "error";
  rows[2].error = "boom";
  BenchSummaryInfo info;
  info.attempts_total = 3;
  const std::string md = bench_summary_markdown(rows, info);
  // 3 attempts, 2 found (67 %), 0 no grasp, 1 error, first FC median 2, mean 2, sd 1.414.
  EXPECT_NE(md.find("| box | h | cord | 3 | 2 (67 %) | 0 | 1 | 2.000 | 2.000 | 1.414 |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| 0.300 | 0.141 |"), std::string::npos) << md;  // α mean, sd
  EXPECT_NE(md.find("1/2 (50 %) | 0.65 |"), std::string::npos) << md;  // sim held, P(held)
  EXPECT_NE(md.find("| h | cord | 3 |"), std::string::npos) << md;   // totals
  EXPECT_NE(md.find("boom"), std::string::npos) << md;
}

TEST(FirstFcCdfSvg, StepsUpOncePerGraspAndStopsAtTheShareFound) {
  EXPECT_EQ(first_fc_cdf_svg({}, 0), "");
  FirstFcPlotParams size;
  size.width_px = 300;
  size.height_px = 200;
  const std::string svg = first_fc_cdf_svg({3.0, 1.0}, 4, size);
  const std::smatch m = [&svg] {
    std::smatch found;
    std::regex_search(svg, found, std::regex(R"re(class="cdf"[^>]*points="([^"]*)")re"));
    return found;
  }();
  ASSERT_EQ(m.size(), 2u) << svg;
  std::vector<std::pair<double, double>> points;
  std::istringstream text(m[1].str());
  for (std::string p; text >> p;)
    points.emplace_back(std::stod(p.substr(0, p.find(','))), std::stod(p.substr(p.find(',') + 1)));
  ASSERT_EQ(points.size(), 2u + 2u * 2u);  // start, two steps of two points, end
  // x grows, y (screen) never goes down the page: a cumulative share.
  for (size_t i = 1; i < points.size(); ++i) {
    EXPECT_GE(points[i].first, points[i - 1].first);
    EXPECT_LE(points[i].second, points[i - 1].second);
  }
  // Two of four found: the curve ends halfway between the 0 % and the 100 % lines, on the
  // dashed line of the share found.
  const double y0 = points.front().second, y_end = points.back().second;
  const double y100 = y0 - 2.0 * (y0 - y_end);
  EXPECT_NEAR(points[2].second, y0 - 0.25 * (y0 - y100), 0.1);  // after the first grasp: 25 %
  std::smatch found;
  ASSERT_TRUE(std::regex_search(svg, found, std::regex(R"re(class="found"[^>]*y1="([^"]*)")re")));
  EXPECT_NEAR(std::stod(found[1].str()), y_end, 0.1);
  EXPECT_LT(y100, y0);
}

TEST(BenchReportHtml, ShowsTheSummaryCellsEveryObjectAndOnlyFilesThatExist) {
  const std::string dir = temp_dir("report");
  std::vector<BenchRow> rows;
  const std::vector<std::string> objects = {"box", "cup <&> \"tall\""};
  for (const std::string& object : objects)
    for (const std::string planner : {"cord", "generic"})
      for (int repeat = 0; repeat < 2; ++repeat) {
        BenchRow r;
        r.attempt = static_cast<int>(rows.size());
        r.object = object;
        r.object_path = object + ".obj";
        r.hand = "h";
        r.planner = planner;
        r.repeat = repeat;
        r.status = repeat == 0 ? "ok" : "no_grasp";
        if (repeat == 0) r.first_fc_s = 0.5 + r.attempt;
        rows.push_back(r);
      }
  rows.back().status = "error";
  rows.back().error = "mesh <broken>";
  fs::create_directories(dir + "/sheets");
  std::ofstream(dir + "/sheets/box.png") << "png";
  BenchSummaryInfo info;
  info.attempts_total = static_cast<int>(rows.size());
  info.command = "cordgrasp bench --objects <many>";
  info.sheets = {"sheets/box.png"};
  write_bench_outputs(dir, rows, {{"format", "cordgrasp-bench"}}, info);
  const std::string html = read_file(dir + "/report.html");
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("</html>"), std::string::npos);
  EXPECT_NE(html.find("<td>box</td>"), std::string::npos);
  EXPECT_NE(html.find("<td>cup &lt;&amp;&gt; &quot;tall&quot;</td>"), std::string::npos) << html;
  EXPECT_EQ(html.find("<many>"), std::string::npos);          // escaped
  EXPECT_NE(html.find("mesh &lt;broken&gt;"), std::string::npos);  // the error row
  EXPECT_NE(html.find("<img class=\"sheet\" src=\"sheets/box.png\""), std::string::npos);
  // The same cells as summary.md, from the same tables.
  const BenchSummaryTables tables = bench_summary_tables(rows);
  ASSERT_EQ(tables.per_object.rows.size(), 4u);
  ASSERT_EQ(tables.totals.rows.size(), 2u);
  for (const auto& row : tables.totals.rows) {
    std::string html_row = "<tr><td>" + row[0] + "</td><td>" + row[1] + "</td>";
    for (size_t i = 2; i < row.size(); ++i) html_row += "<td class=\"num\">" + row[i] + "</td>";
    EXPECT_NE(html.find(html_row + "</tr>"), std::string::npos) << html_row;
  }
  // One plot per hand and planner; the self-test of every report.html.
  EXPECT_EQ(count(html, "<svg class=\"first-fc\""), 2);
  EXPECT_NE(html.find("window.cordgraspSelftest"), std::string::npos);
  EXPECT_EQ(report_link_problems(dir), std::vector<std::string>{});
  // A sheet that is not there is a link the check catches.
  fs::remove(dir + "/sheets/box.png");
  EXPECT_EQ(report_link_problems(dir),
            std::vector<std::string>(2, "links a missing file: sheets/box.png"));
  fs::remove_all(dir);
}

// The CLI runs below use the shipped box and sphere with the default hand, no physics, and a
// time limit far above what these objects need, so no attempt depends on the machine's load.
const std::string kBenchArgs = " --hands cordgrasp_sah --planners cord,generic --repeats 2 "
                               "--time-limit 20 --tests none --no-sheets --quiet";

std::string objects_arg() {
  return " --objects " + quoted(shipped_object("box")) + " " + quoted(shipped_object("sphere"));
}

TEST(CliBench, OneAndTwoJobsGiveTheSameRowsAndShardsMergeToThem) {
  const std::string j1 = temp_dir("j1"), j2 = temp_dir("j2"), s1 = temp_dir("s1"),
                    s2 = temp_dir("s2"), merged = temp_dir("merged");
  auto r = test::run_cordgrasp("bench" + objects_arg() + kBenchArgs + " --jobs 1 --out-dir " +
                               quoted(j1));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = test::run_cordgrasp("bench" + objects_arg() + kBenchArgs + " --jobs 2 --out-dir " +
                          quoted(j2));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto rows1 = read_rows(j1);
  ASSERT_EQ(rows1.size(), 2u * 2u * 2u);
  for (size_t i = 0; i < rows1.size(); ++i) {
    EXPECT_EQ(rows1[i].attempt, static_cast<int>(i));
    EXPECT_EQ(rows1[i].status, "ok") << rows1[i].error;
    EXPECT_TRUE(rows1[i].epsilon && *rows1[i].epsilon > 0.0);
    EXPECT_TRUE(rows1[i].sim_outcome.empty());  // --tests none
  }
  EXPECT_EQ(rows1[0].seed, 1u);
  EXPECT_EQ(rows1[1].seed, 2u);
  EXPECT_TRUE(rows1[0].region_rank.has_value());   // cord
  EXPECT_FALSE(rows1[2].region_rank.has_value());  // generic
  EXPECT_EQ(rows_without_timings(read_rows(j2)), rows_without_timings(rows1));

  for (const auto& [dir, shard] : {std::pair{s1, "1/2"}, std::pair{s2, "2/2"}}) {
    r = test::run_cordgrasp("bench" + objects_arg() + kBenchArgs + " --shard " + shard +
                            " --out-dir " + quoted(dir));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(read_rows(dir).size(), rows1.size() / 2);
  }
  // Merging shard 2 before shard 1 still gives attempt order.
  r = test::run_cordgrasp("merge " + quoted(s2) + " " + quoted(s1) + " --out-dir " +
                          quoted(merged));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(rows_without_timings(read_rows(merged)), rows_without_timings(rows1));
  EXPECT_EQ(report_link_problems(merged), std::vector<std::string>{});
  // Both say which shard commands were merged (summary.md as before: a sub-item per shard).
  EXPECT_EQ(count(read_file(merged + "/report.html"), "<li>merged from: <code>"), 2);
  EXPECT_EQ(count(read_file(merged + "/summary.md"), "\n  - merged from: `"), 2);
  for (const std::string object : {"box", "sphere"})
    EXPECT_NE(read_file(merged + "/report.html").find("<td>" + object + "</td>"),
              std::string::npos) << object;
  const std::string summary = read_file(merged + "/summary.md");
  EXPECT_NE(summary.find("| box | cordgrasp_sah | cord | 2 | 2 (100 %)"), std::string::npos)
      << summary;
  const auto meta = nlohmann::json::parse(read_file(merged + "/bench.json"));
  EXPECT_EQ(meta["attempts"], rows1.size());

  // A shard given twice is rejected; a missing shard too unless --allow-missing.
  const std::string again = temp_dir("again");
  r = test::run_cordgrasp("merge " + quoted(s1) + " " + quoted(s1) + " --out-dir " +
                          quoted(again));
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("appears twice"), std::string::npos) << r.output;
  r = test::run_cordgrasp("merge " + quoted(s1) + " --out-dir " + quoted(again));
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("missing"), std::string::npos) << r.output;
  r = test::run_cordgrasp("merge " + quoted(s1) + " --allow-missing --out-dir " + quoted(again));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  for (const auto& d : {j1, j2, s1, s2, merged, again}) fs::remove_all(d);
}

// bench --uncertainty: each simulated first grasp gets its P(held), decided by the sequential
// test (≥ 5 draws, ≤ validation.max_draws = 20; a threshold of 0.5 decides most grasps in 5),
// the same with one or two threads.
TEST(CliBench, UncertaintyGivesEachFirstGraspItsHoldProbability) {
  constexpr int kMinDraws = 5, kMaxDraws = 20;
  const std::string j1 = temp_dir("hold1"), j2 = temp_dir("hold2");
  const std::string args = " --objects " + quoted(shipped_object("box")) +
                           " --hands cordgrasp_sah --planners cord,generic --repeats 1 "
                           "--time-limit 20 --tests lift --uncertainty realistic "
                           "--min-hold-probability 0.5 --no-sheets "
                           "--quiet --out-dir ";
  auto r = test::run_cordgrasp("bench" + args + quoted(j1) + " --jobs 1");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = test::run_cordgrasp("bench" + args + quoted(j2) + " --jobs 2");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto rows = read_rows(j1);
  ASSERT_EQ(rows.size(), 2u);
  for (const BenchRow& row : rows) {
    ASSERT_EQ(row.status, "ok") << row.error;
    ASSERT_TRUE(row.hold_p && row.hold_low && row.hold_high && row.hold_draws && row.hold_cpu_s);
    EXPECT_LE(*row.hold_low, *row.hold_p);
    EXPECT_LE(*row.hold_p, *row.hold_high);
    EXPECT_GE(*row.hold_draws, kMinDraws);
    EXPECT_LE(*row.hold_draws, kMaxDraws);
    EXPECT_GT(*row.hold_cpu_s, 0.0);
  }
  EXPECT_EQ(rows_without_timings(read_rows(j2)), rows_without_timings(rows));
  const auto meta = nlohmann::json::parse(read_file(j1 + "/bench.json"));
  EXPECT_TRUE(meta["parameters"]["uncertainty"].is_object()) << meta.dump();
  EXPECT_NE(read_file(j1 + "/summary.md").find("P(held) median"), std::string::npos);
  // Without --uncertainty the columns stay empty.
  const std::string none = temp_dir("hold_none");
  r = test::run_cordgrasp("bench --objects " + quoted(shipped_object("box")) +
                          " --hands cordgrasp_sah --planners cord --tests lift --no-sheets "
                          "--quiet --out-dir " + quoted(none));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_FALSE(read_rows(none).at(0).hold_p.has_value());
  for (const auto& d : {j1, j2, none}) fs::remove_all(d);
}

// bench takes the planner's settings from a settings file, as plan does: a row is repeated by
// `plan --settings FILE --seed <seed>`; the planner's tuning flags are not options of bench.
TEST(CliBench, SettingsFileTunesThePlannerAsForPlan) {
  const std::string dir = temp_dir("settings"), out = dir + "/out";
  const std::string settings = dir + "/few_sets.yaml";
  std::ofstream(settings) << "cord: {sets: 3, local_improvement: false}\nmax_attempts: 40\n";
  auto r = test::run_cordgrasp("bench --objects " + quoted(shipped_object("box")) +
                               " --hands cordgrasp_sah --planners cord --repeats 1 --seed 4 "
                               "--tests none --no-sheets --quiet --settings " + quoted(settings) +
                               " --out-dir " + quoted(out));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto meta = nlohmann::json::parse(read_file(out + "/bench.json"));
  EXPECT_EQ(meta["parameters"]["job"]["cord"]["sets"], 3) << meta.dump();
  EXPECT_EQ(meta["parameters"]["job"]["cord"]["local_improvement"], false);
  EXPECT_EQ(meta["parameters"]["job"]["plan"]["max_attempts"], 40);
  const BenchRow row = read_rows(out).at(0);
  ASSERT_EQ(row.status, "ok") << row.error;
  EXPECT_LE(row.finger_attempts, 40);
  r = test::run_cordgrasp("plan --object " + quoted(shipped_object("box")) + " --seed 4 " +
                          "--settings " + quoted(settings) + " -q --out " +
                          quoted(dir + "/plan.json"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto plan = nlohmann::json::parse(read_file(dir + "/plan.json"));
  EXPECT_EQ(plan["stats"]["attempts"], row.finger_attempts);
  EXPECT_NEAR(plan["grasps"][0]["epsilon"].get<double>(), *row.epsilon, 1e-6 * *row.epsilon);
  r = test::run_cordgrasp("bench --objects " + quoted(shipped_object("box")) +
                          " --hands cordgrasp_sah --sets 3 --tests none --out-dir " +
                          quoted(dir + "/refused"));
  EXPECT_NE(r.exit_code, 0) << r.output;
  fs::remove_all(dir);
}

TEST(CliBench, BadMeshIsAnErrorRowAndTheBenchExitsZero) {
  const std::string dir = temp_dir("bad"), out = dir + "/out";
  const std::string bad = dir + "/broken.obj";
  std::ofstream(bad) << "this is not a mesh\n";
  const std::string args = " --objects " + quoted(bad) + " " + quoted(shipped_object("box")) +
                           " --hands cordgrasp_sah --planners cord --repeats 1 --time-limit 20 "
                           "--quiet --out-dir " + quoted(out);
  auto r = test::run_cordgrasp("bench" + args + " --tests lift --sheet-size 160x120");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto rows = read_rows(out);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].object, "broken");
  EXPECT_EQ(rows[0].status, "error");
  EXPECT_NE(rows[0].error.find("broken.obj"), std::string::npos) << rows[0].error;
  EXPECT_EQ(rows[1].status, "ok") << rows[1].error;
  EXPECT_FALSE(rows[1].sim_lift.empty());          // lift was simulated
  EXPECT_EQ(rows[1].sim_shake, "not_run");         // not requested
  EXPECT_FALSE(rows[1].sim_outcome.empty());
  EXPECT_NE(read_file(out + "/summary.md").find("## Errors"), std::string::npos);
  EXPECT_GT(fs::file_size(out + "/sheets/box.png"), 0u);
  EXPECT_FALSE(fs::exists(out + "/sheets/broken.png"));
  // report.html: every object, the contact sheet as an image, only files that exist.
  const std::string html = read_file(out + "/report.html");
  EXPECT_NE(html.find("<td>broken</td>"), std::string::npos);
  EXPECT_NE(html.find("<td>box</td>"), std::string::npos);
  EXPECT_NE(html.find("src=\"sheets/box.png\""), std::string::npos);
  EXPECT_EQ(report_link_problems(out), std::vector<std::string>{});
  // A second bench into the same folder is refused without --overwrite; nothing is replaced.
  const std::string before = read_file(out + "/results.csv");
  r = test::run_cordgrasp("bench" + args + " --tests none --no-sheets");
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("holds another bench's results.csv"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--overwrite"), std::string::npos) << r.output;
  EXPECT_EQ(read_file(out + "/results.csv"), before);
  // --strict turns error rows into exit code 2 (rows are still written).
  r = test::run_cordgrasp("bench" + args + " --tests none --no-sheets --strict --overwrite");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(read_rows(out).size(), 2u);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cordgrasp
