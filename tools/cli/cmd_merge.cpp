// `cordgrasp merge`: joins the outputs of `cordgrasp bench --shard k/N` runs into one
// results.csv (attempt order), summary.md and report.html. See docs/bench.md.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>

#include "cordgrasp/jobs/bench_job.h"
#include "cordgrasp/jobs/json_completeness.h"
#include "commands.h"
#include "cordgrasp/core/error.h"
#include "cordgrasp/core/version.h"

namespace cordgrasp::cli {
namespace {

namespace fs = std::filesystem;

struct MergeOptions {
  std::vector<std::string> dirs;
  bool allow_missing = false;
  std::string out_dir;
};

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("merge: '" + path.string() + "': cannot open");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void run_merge(const MergeOptions& opt) {
  std::vector<std::vector<BenchRow>> parts;
  nlohmann::json parameters;
  int attempts_total = -1;
  std::string tests;
  nlohmann::json sources = nlohmann::json::array();
  std::string interrupted;  // of the first shard that was stopped early, if any
  for (const std::string& dir : opt.dirs) {
    const fs::path meta_path = fs::path(dir) / "bench.json";
    nlohmann::json meta;
    try {
      meta = nlohmann::json::parse(read_file(meta_path));
    } catch (const nlohmann::json::exception& e) {
      throw InputError("merge: '" + meta_path.string() + "': not JSON: " + e.what());
    }
    if (meta.value("format", "") != "cordgrasp-bench")
      throw InputError("merge: '" + meta_path.string() + "': not a cordgrasp bench output");
    if (interrupted.empty())
      interrupted = read_interrupted(meta, "merge: '" + meta_path.string() + "'");
    if (parameters.is_null()) {
      parameters = meta.at("parameters");
      attempts_total = meta.at("attempts_total").get<int>();
      tests = parameters.value("tests", "");
    } else if (meta.at("parameters") != parameters ||
               meta.at("attempts_total").get<int>() != attempts_total) {
      throw InputError("merge: '" + dir + "' was run with other bench parameters than '" +
                       opt.dirs.front() + "' (compare their bench.json)");
    }
    parts.push_back(parse_bench_csv(read_file(fs::path(dir) / "results.csv"),
                                    (fs::path(dir) / "results.csv").string()));
    sources.push_back({{"dir", dir}, {"shard", meta.value("shard", nlohmann::json())},
                       {"command", meta.value("command", "")}});
  }
  const std::vector<BenchRow> rows = merge_bench_rows(parts);
  const int missing = attempts_total - static_cast<int>(rows.size());
  if (missing > 0) {
    std::set<int> have;
    for (const BenchRow& r : rows) have.insert(r.attempt);
    std::string first;
    for (int i = 0, listed = 0; i < attempts_total && listed < 10; ++i)
      if (!have.count(i)) first += (listed++ ? ", " : "") + std::to_string(i);
    const std::string message = "merge: " + std::to_string(missing) + " of " +
                                std::to_string(attempts_total) +
                                " attempts missing (first: " + first + "); a shard not given?";
    if (!opt.allow_missing) throw InputError(message + " (--allow-missing to merge anyway)");
    std::cerr << "cordgrasp: warning: " << message << '\n';
  }
  BenchSummaryInfo info;
  info.command = process_command_line();
  for (const auto& s : sources)
    if (!s["command"].get<std::string>().empty())
      info.merged_from.push_back(s["command"].get<std::string>());
  info.machine = machine_description() + " (merge; shards may have run elsewhere: see bench.json)";
  info.attempts_total = attempts_total;
  info.tests = tests;
  nlohmann::json meta = {{"format", "cordgrasp-bench"},
                         {"format_version", 1},
                         {"cordgrasp_version", version()},
                         {"command", process_command_line()},
                         {"machine", machine_description()},
                         {"parameters", parameters},
                         {"attempts_total", attempts_total},
                         {"attempts", rows.size()},
                         {"shard", nullptr},
                         {"merged_from", sources}};
  mark_completeness(&meta, interrupted);
  if (missing > 0) meta["complete"] = false;
  write_bench_outputs(opt.out_dir, rows, meta, info);
  std::printf("merge: %zu rows from %zu directories -> %s\n", rows.size(), opt.dirs.size(),
              (fs::path(opt.out_dir) / "results.csv").string().c_str());
}

}  // namespace


void add_merge_command(CLI::App& app) {
  auto opt = std::make_shared<MergeOptions>();
  CLI::App* cmd = app.add_subcommand(
      "merge", "Join `cordgrasp bench --shard k/N` outputs into one results.csv, summary.md and "
               "report.html");
  cmd->add_option("dirs", opt->dirs, "Bench output directories (one per shard)")->required();
  cmd->add_flag("--allow-missing", opt->allow_missing,
                "Merge even when some attempts are in no directory (a shard missing)");
  cmd->add_option("--out-dir", opt->out_dir, "Output directory (created)")->required();
  cmd->callback([opt]() { run_merge(*opt); });
}

}  // namespace cordgrasp::cli
