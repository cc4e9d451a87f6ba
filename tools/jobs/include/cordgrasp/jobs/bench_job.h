#pragma once
// `cordgrasp bench` / `cordgrasp merge`: the list of attempts (object × hand ×
// planner × repeat), one attempt run in-process, the results.csv row, the thread pool, shards,
// merging and summary.md.
//
// Attempt order: objects (as given, directories expanded to their sorted mesh files), then
// hands, then planners, then repeats; attempt i of that list has index i. The seed of repeat
// r is `--seed` + r (repeat_seed), the same for every object, hand and planner, so any row is
// reproduced by `cordgrasp plan --seed <seed>` with the bench's options.
#include <cstdint>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cordgrasp/core/cancel_token.h"
#include "cordgrasp/core/grasp.h"
#include "cordgrasp/core/hand_description.h"
#include "cordgrasp/core/hand_model.h"
#include "cordgrasp/core/mesh.h"
#include "cordgrasp/jobs/plan_job.h"
#include "cordgrasp/sim/grasp_uncertainty.h"
#include "cordgrasp/sim/grasp_validation.h"
#include "cordgrasp/sim/hold_probability.h"
#include "cordgrasp/sim/sim_params.h"

namespace cordgrasp {

/// What a bench run is configured by (bench.json "parameters"; shards must agree on it).
struct BenchParams {
  std::vector<std::string> hands;     ///< hand names or description files
  std::vector<std::string> objects;   ///< mesh files (directories already expanded)
  std::vector<PlannerKind> planners;  ///< cord and/or generic
  int repeats = 1;                    ///< attempts per (object, hand, planner)
  std::uint64_t seed = 1;             ///< seed of repeat 0 (repeat r: seed + r)
  PlanJobParams job;                  ///< planner options (planner and seed set per attempt)
  std::string tests = "lift,shake";   ///< physics tests on each attempt's first grasp; "none"
  Protocol protocol = SimParams{}.protocol;  ///< physics protocol preset
  std::string sim_cache_dir;          ///< on-disk convex decomposition cache ("" = memory only)
  std::string physics_file;           ///< physics settings file over the protocol ("" = none)
  /// Set: each attempt plans with validated_plan_job (its tests and protocol: from above)
  /// and fills the validated_* columns.
  std::optional<ValidationParams> validation;
  /// Not none: each simulated first grasp also gets its P(held) under this model
  /// (estimate_hold_probability with hold_test; the hold_* columns).
  UncertaintyParams uncertainty = uncertainty_none();
  HoldProbabilityParams hold_test;    ///< the sequential test of that P(held)
  HandLoadOptions hand_load;          ///< package:// directories of the hands' URDFs
};

/// One attempt: plan (and validate the first grasp of) one object with one hand and planner.
struct BenchAttempt {
  int index = 0;            ///< position in the full attempt list (bench_attempts)
  std::string object_path;  ///< as given (directories expanded)
  std::string hand;         ///< as given to --hands
  PlannerKind planner = PlannerKind::kCord;
  int repeat = 0;           ///< 0-based
  std::uint64_t seed = 0;   ///< repeat_seed(params.seed, repeat)
};

/// Seed of repeat `repeat` (0-based): base_seed + repeat.
std::uint64_t repeat_seed(std::uint64_t base_seed, int repeat);

/// Mesh files named by `args`: a file as is, a directory as its .obj/.stl/.ply/.off files
/// (sorted, not recursive). @throws InputError for a path that does not exist or a directory
/// without meshes.
std::vector<std::string> expand_object_args(const std::vector<std::string>& args);

/// Every attempt of `params`, in attempt order (see top of file).
std::vector<BenchAttempt> bench_attempts(const BenchParams& params);

/// Parses "k/N" (1 <= k <= N). @throws InputError otherwise.
std::pair<int, int> parse_shard(const std::string& text);

/// The attempts of shard k of N: those whose index mod N == k − 1.
std::vector<BenchAttempt> shard_attempts(const std::vector<BenchAttempt>& attempts, int k, int n);

/// One results.csv row. Optional fields are empty cells when absent.
struct BenchRow {
  int attempt = 0;
  std::string object;  ///< mesh file name without extension
  std::string object_path;
  std::string hand;
  std::string planner;
  int repeat = 0;
  std::uint64_t seed = 0;
  std::string status;  ///< ok (≥ 1 force-closure grasp), no_grasp, error
  std::string error;   ///< the exception's message (status error)
  std::optional<double> first_fc_s;  ///< plan start → first force-closure grasp [s]
  double exploration_s = 0.0, finger_s = 0.0, quality_s = 0.0, total_s = 0.0;  ///< [s]
  int regions = 0;            ///< cord: regions explored
  int regions_processed = 0;  ///< cord: regions given to the finger stage
  int finger_attempts = 0;    ///< finger-stage runs
  int grasps = 0;             ///< force-closure grasps found
  bool timed_out = false;
  std::optional<double> epsilon;    ///< first grasp
  std::optional<double> alpha_rad;  ///< first grasp, palm normal (Grasp::alpha_rad)
  std::optional<double> alpha_approach_rad;  ///< first grasp, GCP z axis
  std::optional<double> chi_m2;     ///< first grasp (cord)
  std::optional<int> region_rank;   ///< first grasp (cord; 0 = lowest χ)
  std::string sim_lift, sim_shake, sim_gravity6;  ///< phase outcome; "" = not simulated
  std::string sim_outcome;                         ///< overall; "" = not simulated
  std::optional<double> sim_wall_s;                ///< [s]
  double object_scale = 1.0;                       ///< --scale the object was loaded with
  /// Validated planning (BenchParams::validation; unset otherwise): accepted grasps,
  /// force-closure candidates, candidates simulated, rejected early by the squeeze shift, held
  /// as planned, CPU to the first accepted grasp [s] and of the whole plan [s].
  std::optional<int> validated_accepted, validated_candidates, validated_simulated,
      validated_rejected_early, validated_held_as_planned;
  std::optional<double> validated_first_accepted_cpu_s, validated_cpu_s;
  /// P(held) of the first grasp under BenchParams::uncertainty (unset without it): the
  /// estimate, its Wilson 95 % interval, the draws it took and their CPU time [s].
  std::optional<double> hold_p, hold_low, hold_high;
  std::optional<int> hold_draws;
  std::optional<double> hold_cpu_s;
};

/// Column names of results.csv, in order.
const std::vector<std::string>& bench_csv_columns();

/// Columns that hold wall-clock times (differ between runs of the same attempt).
const std::vector<std::string>& bench_timing_columns();

/// One row as CSV cells (bench_csv_columns order, RFC 4180 quoting not applied).
std::vector<std::string> bench_row_cells(const BenchRow& row);

/// results.csv text: header, then rows as given.
std::string bench_csv(const std::vector<BenchRow>& rows);

/// Parses results.csv text; `what` names the source in errors. @throws InputError for a
/// wrong header or a malformed row.
std::vector<BenchRow> parse_bench_csv(const std::string& text, const std::string& what);

/// Objects and hands loaded once and shared read-only by every attempt (a failed load is kept
/// as its message and makes the attempts using it error rows).
class BenchInputs {
 public:
  /// Loads every object (load_job_mesh: units from params.job.units) and hand of `params`
  /// that `attempts` use.
  BenchInputs(const BenchParams& params, const std::vector<BenchAttempt>& attempts);
  /// The mesh, or nullptr with *error set.
  std::shared_ptr<const Mesh> mesh(const std::string& path, std::string* error) const;
  /// The hand, or nullptr with *error set.
  const HandModel* hand(const std::string& name, std::string* error) const;

 private:
  struct Loaded;
  std::shared_ptr<const Loaded> loaded_;
};

/// A row and, when the attempt found one, its first grasp (for contact sheets).
struct BenchResult {
  BenchRow row;
  std::optional<Grasp> first_grasp;  ///< carries its cord region
  /// Stopped by a CancelToken before it finished (or before it began): not a result, no row.
  bool interrupted = false;
};

/// Runs one attempt: plan_job, then (unless tests are "none") validate_plan of the first grasp
/// with the plan's μ. Never throws: failures become status "error". `cancel` reaches the
/// planner and the physics: an attempt it cut short comes back with `interrupted` set.
BenchResult run_bench_attempt(const BenchAttempt& attempt, const BenchParams& params,
                              const BenchInputs& inputs, const CancelToken& cancel = {});

/// Called after each finished attempt (from the worker thread, serialized): done, total, row.
using BenchProgress = std::function<void(int done, int total, const BenchRow& row)>;

/// Runs `attempts` on `jobs` threads (each attempt independent); results in the order of
/// `attempts`, whatever `jobs`. Once `cancel` is set no attempt starts and those in flight are
/// abandoned: their results have `interrupted` set (progress is called for finished ones only).
std::vector<BenchResult> run_bench_attempts(const std::vector<BenchAttempt>& attempts,
                                            const BenchParams& params, const BenchInputs& inputs,
                                            int jobs, const BenchProgress& progress = {},
                                            const CancelToken& cancel = {});

/// bench.json "parameters": everything rows depend on (not --jobs, --shard, output options);
/// "job" holds every PlanJobParams field but the planner (its Serialize visitor).
nlohmann::json bench_params_to_json(const BenchParams& params);

/// Rows of several shard outputs, sorted by attempt. @throws InputError when two rows share an
/// attempt index.
std::vector<BenchRow> merge_bench_rows(const std::vector<std::vector<BenchRow>>& parts);

/// What summary.md says besides the rows.
struct BenchSummaryInfo {
  std::string command;     ///< the command line
  std::vector<std::string> merged_from;  ///< merge: the command lines of the shards merged
  std::string machine;     ///< e.g. "2 cores (nproc), Intel(R) Xeon(R) ..."
  int attempts_total = 0;  ///< attempts of the whole bench (all shards)
  std::string shard;       ///< "k/N", or "" for a whole bench
  std::string tests;       ///< physics tests run on the first grasps
  std::vector<std::string> sheets;  ///< contact sheet files (relative to the output dir)
  std::string interrupted;  ///< the signal that stopped the bench early ("SIGINT"), or ""
  int attempts_asked = 0;   ///< attempts this run (its shard) was to make, when interrupted
};

/// A table of summary.md and report.html: column names and rows of cells (text, units in the
/// column names).
struct BenchSummaryTable {
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;
};

/// The summary's tables, groups in attempt order: per object × hand × planner, and per hand ×
/// planner over all objects (attempts, grasps found, no grasp, errors, time to the first
/// force-closure grasp, total time, α, ε, sim hold rate).
struct BenchSummaryTables {
  BenchSummaryTable per_object;
  BenchSummaryTable totals;
};

/// The summary's tables of `rows` (summary.md and report.html show the same cells).
BenchSummaryTables bench_summary_tables(const std::vector<BenchRow>& rows);

/// summary.md: per object × hand × planner, then per hand × planner over all objects, then
/// errors.
std::string bench_summary_markdown(const std::vector<BenchRow>& rows,
                                   const BenchSummaryInfo& info);

/// Writes results.csv, summary.md, bench.json (`bench_json`) and report.html
/// (bench_report_html) into `out_dir` (created if missing), each atomically.
/// @throws InputError when a file cannot be written.
void write_bench_outputs(const std::string& out_dir, const std::vector<BenchRow>& rows,
                         const nlohmann::json& bench_json, const BenchSummaryInfo& info);

/// "N cores (nproc), <CPU model from /proc/cpuinfo>".
std::string machine_description();

/// The process's command line from /proc/self/cmdline, shell-quoted where needed.
std::string process_command_line();

}  // namespace cordgrasp
