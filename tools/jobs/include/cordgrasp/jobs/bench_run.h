#pragma once
// `cordgrasp bench` as a job: every object × hand × planner × repeat (threads, shards), then
// results.csv, summary.md, report.html, bench.json and contact sheets.
#include <functional>
#include <string>
#include <vector>

#include "cordgrasp/jobs/bench_job.h"

namespace cordgrasp {

/// Inputs and settings of run_bench().
struct BenchRunParams {
  std::vector<std::string> hands;       ///< names or files; items may be comma separated
  std::vector<std::string> objects;     ///< mesh files and/or directories
  std::vector<std::string> planners;    ///< cord and/or generic
  int repeats = 1;                      ///< attempts per object, hand and planner
  PlanJobParams job;                    ///< planner settings (seed: repeat r uses seed + r)
  std::string tests = "lift,shake";     ///< physics tests on each first grasp, or "none"
  Protocol protocol = SimParams{}.protocol; ///< physics protocol preset
  std::string cache_dir;                ///< on-disk convex decomposition cache ("" = none)
  HandLoadOptions hand_load;            ///< package:// directories of the hands' URDFs
  int jobs = 1;                         ///< threads
  bool validate = false;                ///< validated planning per attempt (validated_* columns)
  ValidationParams validation;          ///< its settings (tests, protocol: from above)
  std::string shard;                    ///< "k/N": one deterministic slice ("" = all)
  bool no_sheets = false;               ///< no contact sheet PNGs
  std::string sheet_size = "480x360";   ///< contact sheet tile size WxH [px]
  std::string out_dir;                  ///< output folder (created)
  bool overwrite = false;  ///< replace the results and report.html in out_dir (else refused)
  /// Stop request: no attempt starts once it is set, those in flight are abandoned; the rows
  /// finished are written with bench.json "complete": false (no contact sheets).
  CancelToken cancel;
};

/// What run_bench() wrote.
struct BenchRunOutcome {
  std::vector<BenchRow> rows;
  int ok = 0;                ///< attempts with a force-closure grasp
  int errors = 0;            ///< attempts that failed with an error
  std::string results_csv;   ///< path of results.csv
  int attempts_asked = 0;    ///< attempts of this run (its shard)
  std::string interrupted;   ///< the signal that stopped it early ("SIGINT"), or ""
};

/// Messages of a bench run: `note` (start line), `warning`, and per-attempt progress.
struct BenchRunCallbacks {
  std::function<void(const std::string&)> note;
  std::function<void(const std::string&)> warning;
  BenchProgress progress;
};

/// Runs the attempts of p (its shard) and writes the outputs to p.out_dir.
/// @throws InputError for bad options or an output folder that cannot be made.
BenchRunOutcome run_bench(const BenchRunParams& p, const BenchRunCallbacks& callbacks = {});

}  // namespace cordgrasp
