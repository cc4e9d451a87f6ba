// `cordgrasp bench`: plan (and validate) every object × hand × planner × repeat, in parallel
// threads or as one shard of many, into results.csv, summary.md, report.html, bench.json and
// contact sheets. See docs/bench.md.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "commands.h"
#include "cordgrasp/core/error.h"
#include "cordgrasp/jobs/bench_run.h"
#include "options.h"
#include "validation_options.h"

namespace cordgrasp::cli {
namespace {

std::string clock_text(double s) {
  const long t = std::lround(std::max(0.0, s));
  char buf[32];
  if (t >= 3600)
    std::snprintf(buf, sizeof(buf), "%ld:%02ld:%02ld", t / 3600, t / 60 % 60, t % 60);
  else
    std::snprintf(buf, sizeof(buf), "%ld:%02ld", t / 60, t % 60);
  return buf;
}

// Progress on stderr: a redrawn bar on a terminal, one line per attempt otherwise (logs).
class ProgressBar {
 public:
  explicit ProgressBar(bool enabled) : enabled_(enabled), tty_(isatty(STDERR_FILENO)) {}
  void update(int done, int total, const BenchRow& row) {
    if (!enabled_) return;
    const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
    const double eta = done > 0 ? elapsed / done * (total - done) : 0.0;
    constexpr int kWidth = 30;
    const int filled = total > 0 ? kWidth * done / total : kWidth;
    std::string bar(filled, '#');
    bar += std::string(kWidth - filled, '.');
    const std::string last = row.object + " " + row.hand + " " + row.planner + " r" +
                             std::to_string(row.repeat) + ": " + row.status;
    if (tty_) {
      std::fprintf(stderr, "\rbench [%s] %d/%d  elapsed %s  ETA %s  %-40.40s", bar.c_str(), done,
                   total, clock_text(elapsed).c_str(), clock_text(eta).c_str(), last.c_str());
      if (done == total) std::fputc('\n', stderr);
    } else {
      std::fprintf(stderr, "bench: %d/%d  elapsed %s  ETA %s  %s\n", done, total,
                   clock_text(elapsed).c_str(), clock_text(eta).c_str(), last.c_str());
    }
    std::fflush(stderr);
  }

 private:
  using Clock = std::chrono::steady_clock;
  bool enabled_;
  bool tty_;
  Clock::time_point start_ = Clock::now();
};

}  // namespace

void add_bench_command(CLI::App& app) {
  struct Options {
    BenchRunParams bench;
    bool strict = false;
    bool quiet = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "bench", "Benchmark planners over objects × hands × repeats: results.csv, summary.md, "
               "report.html, contact sheets (docs/bench.md)");
  cmd->add_option("--hands", opt->bench.hands, "Hands (names or files), comma separated")->required();
  add_package_path_option(cmd, opt->bench.hand_load);
  cmd->add_option("--objects", opt->bench.objects,
                  "Object mesh files and/or directories (their .obj/.stl/.ply/.off files)")
      ->required();
  cmd->add_option("--planners", opt->bench.planners, "cord, generic or cord,generic")
      ->default_val("cord");
  cmd->add_option("--repeats", opt->bench.repeats,
                  "Attempts per object, hand and planner; repeat r uses seed --seed + r")
      ->check(whole_number_in(1, 100000))
      ->capture_default_str();
  add_plan_job_options(cmd, opt->bench.job);
  add_units_option(cmd, opt->bench.job);
  add_scale_option(cmd, &opt->bench.job.scale);
  add_time_limit_option(cmd, opt->bench.job);
  add_plan_settings_option(cmd, opt->bench.job, opt->bench.validation);
  cmd->add_option("--tests", opt->bench.tests,
                  "Physics tests on each attempt's first grasp: lift,shake,gravity6 subset, or "
                  "none")
      ->capture_default_str();
  add_enum_option(cmd, "--protocol", &opt->bench.protocol,
                  kProtocolHelp);
  cmd->add_option("--cache-dir", opt->bench.cache_dir,
                  "Directory caching convex decompositions on disk (by mesh hash)");
  cmd->add_option("--jobs,-j", opt->bench.jobs, "Attempts run in parallel threads")
      ->check(whole_number_in(1, 256))
      ->capture_default_str();
  cmd->add_option("--shard", opt->bench.shard,
                  "k/N: run only attempts whose index mod N = k-1 (join with cordgrasp merge)");
  cmd->add_flag("--validate", opt->bench.validate,
                "Validated planning per attempt (plan --validate); adds the validated_* columns");
  cmd->add_option("--physics", opt->bench.validation.physics_file, kPhysicsHelp);
  add_uncertainty_options(cmd, opt->bench.validation,
                          "Each simulated first grasp's P(held) (hold_* columns)");
  cmd->add_flag("--no-sheets", opt->bench.no_sheets, "No contact sheet PNGs");
  cmd->add_option("--sheet-size", opt->bench.sheet_size, "Contact sheet tile size WxH [px]")
      ->capture_default_str();
  cmd->add_flag("--strict", opt->strict, "Exit 2 when any attempt is an error row");
  cmd->add_flag("--quiet,-q", opt->quiet, "No progress on stderr");
  cmd->add_option("--out-dir", opt->bench.out_dir, "Output directory (created)")->required();
  cmd->add_flag("--overwrite", opt->bench.overwrite,
                "Replace the results.csv, bench.json, summary.md and report.html in --out-dir");
  cmd->callback([opt]() {
    BenchRunCallbacks cb;
    auto bar = std::make_shared<ProgressBar>(!opt->quiet);
    cb.progress = [bar](int done, int total, const BenchRow& row) { bar->update(done, total, row); };
    if (!opt->quiet) {
      cb.note = [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); };
      cb.warning = [](const std::string& line) {
        std::fprintf(stderr, "cordgrasp: warning: %s\n", line.c_str());
      };
    }
    install_interrupt_handlers();
    opt->bench.cancel = interrupt_token();
    const BenchRunOutcome out = run_bench(opt->bench, cb);
    if (!out.interrupted.empty() && !opt->quiet && isatty(STDERR_FILENO))
      std::fputc('\n', stderr);  // end the progress bar's line
    std::printf("bench: %d/%zu attempts found a force-closure grasp, %d errors -> %s\n", out.ok,
                out.rows.size(), out.errors, out.results_csv.c_str());
    if (out.errors > 0 && !opt->quiet)
      std::fprintf(stderr, "cordgrasp: warning: bench: %d attempt(s) failed; see the error "
                           "column of results.csv\n", out.errors);
    if (!out.interrupted.empty()) {
      std::printf("bench: interrupted by %s after %zu of %d attempts (those in flight "
                  "abandoned); %s holds those rows, bench.json marked incomplete\n",
                  out.interrupted.c_str(), out.rows.size(), out.attempts_asked,
                  opt->bench.out_dir.c_str());
      throw Interrupted("interrupted by " + out.interrupted);
    }
    if (out.errors > 0 && opt->strict) throw CLI::RuntimeError(2);
  });
}

}  // namespace cordgrasp::cli
