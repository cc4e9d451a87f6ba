// `cordgrasp bench`: plan (and validate) every object × hand × planner × repeat, in parallel
// threads or as one shard of many, into results.csv, summary.md, bench.json and contact
// sheets (issue 7). See docs/bench.md.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

#include "cordgrasp/jobs/bench_job.h"
#include "commands.h"
#include "options.h"
#include "cordgrasp/core/error.h"
#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/core/version.h"
#include "cordgrasp/render/contact_sheet.h"
#include "cordgrasp/render/png_io.h"
#include "cordgrasp/render/renderer.h"
#include "cordgrasp/sim/validate_grasp.h"
#include "cordgrasp/jobs/hand_scene.h"
#include "cordgrasp/jobs/render_options.h"

namespace cordgrasp::cli {
namespace {

namespace fs = std::filesystem;

struct BenchOptions {
  std::vector<std::string> hands;
  std::vector<std::string> objects;
  std::vector<std::string> planners;
  int repeats = 1;
  PlanJobParams job;
  std::string tests = "lift,shake";
  std::string cache_dir;
  int jobs = 1;
  std::string shard;
  bool no_sheets = false;
  std::string sheet_size = "480x360";
  bool strict = false;
  bool quiet = false;
  std::string out_dir;
};

std::vector<std::string> split_commas(const std::vector<std::string>& items) {
  std::vector<std::string> out;
  for (const std::string& item : items) {
    std::stringstream s(item);
    for (std::string part; std::getline(s, part, ',');)
      if (!part.empty()) out.push_back(part);
  }
  return out;
}

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

std::string file_part(const std::string& text) {
  std::string out = text;
  for (char& c : out)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '+' && c != '.') c = '_';
  return out;
}

// One PNG per object: for each hand and planner, the attempt whose first grasp has the highest
// ε. Returns the written files relative to out_dir. Rendering failures are warnings.
std::vector<std::string> write_contact_sheets(const std::vector<BenchResult>& results,
                                              const BenchInputs& inputs,
                                              const std::string& size,
                                              const std::string& out_dir, bool quiet) {
  std::vector<std::string> objects;  // in attempt order
  std::map<std::string, std::vector<const BenchResult*>> best;  // object → per hand×planner
  for (const BenchResult& r : results) {
    if (!r.first_grasp) continue;
    auto& list = best[r.row.object_path];
    if (list.empty()) objects.push_back(r.row.object_path);
    bool placed = false;
    for (const BenchResult*& b : list) {
      if (b->row.hand == r.row.hand && b->row.planner == r.row.planner) {
        if (r.first_grasp->epsilon > b->first_grasp->epsilon) b = &r;
        placed = true;
      }
    }
    if (!placed) list.push_back(&r);
  }
  std::vector<std::string> written;
  if (objects.empty()) return written;
  const fs::path dir = fs::path(out_dir) / "sheets";
  try {
    fs::create_directories(dir);
    Renderer renderer;
    std::map<std::string, HandMeshes> hand_meshes;
    PictureOptions picture;
    picture.size = size;
    picture.no_caption = true;
    for (const std::string& object_path : objects) {
      const auto mesh = inputs.mesh(object_path, nullptr);
      if (!mesh) continue;
      std::vector<Image> tiles;
      std::vector<std::string> captions;
      for (const BenchResult* b : best[object_path]) {
        const HandModel* hand = inputs.hand(b->row.hand, nullptr);
        if (!hand) continue;
        if (!hand_meshes.count(b->row.hand)) hand_meshes[b->row.hand] = make_hand_meshes(*hand);
        const Grasp& g = *b->first_grasp;
        OverlayStyle overlay;
        Scene scene = grasp_scene(*hand, hand_meshes[b->row.hand], mesh, g,
                                  g.region ? &*g.region : nullptr, overlay);
        const RenderParams params = render_params(picture, scene);
        tiles.push_back(renderer.render(scene, params));
        char caption[160];
        std::snprintf(caption, sizeof(caption), "%s · %s · α %.3f rad · ε %.3g · %s",
                      b->row.hand.c_str(), b->row.planner.c_str(), g.alpha_rad, g.epsilon,
                      b->row.sim_outcome.empty() ? "not simulated" : b->row.sim_outcome.c_str());
        captions.push_back(caption);
      }
      if (tiles.empty()) continue;
      ContactSheetParams sheet;
      sheet.title = mesh->name + " · best first grasp (highest ε) per hand and planner";
      const std::string name = "sheets/" + file_part(fs::path(object_path).stem().string()) +
                               ".png";
      write_png((fs::path(out_dir) / name).string(),
                compose_contact_sheet(tiles, captions, sheet));
      written.push_back(name);
    }
  } catch (const std::exception& e) {
    if (!quiet)
      std::cerr << "cordgrasp: warning: bench: contact sheets not rendered: " << e.what() << '\n';
  }
  return written;
}

int run_bench(const BenchOptions& opt) {
  BenchParams params;
  params.hands = split_commas(opt.hands);
  params.planners = split_commas(opt.planners);
  for (const std::string& p : params.planners)
    if (p != "cord" && p != "generic")
      throw InputError("bench: --planners: '" + p + "' is not cord or generic");
  params.objects = expand_object_args(opt.objects);
  params.repeats = opt.repeats;
  params.seed = opt.job.plan.seed;
  params.job = opt.job;
  params.tests = opt.tests;
  params.sim_cache_dir = opt.cache_dir;
  if (params.tests != "none") (void)sim_tests_from_string(params.tests);  // fail early
  const auto [shard_k, shard_n] = opt.shard.empty() ? std::pair{1, 1} : parse_shard(opt.shard);

  const std::vector<BenchAttempt> all = bench_attempts(params);
  const std::vector<BenchAttempt> attempts = shard_attempts(all, shard_k, shard_n);
  std::error_code ec;
  fs::create_directories(opt.out_dir, ec);
  if (ec) throw InputError("bench: cannot create '" + opt.out_dir + "': " + ec.message());
  if (!opt.quiet)
    std::fprintf(stderr, "bench: %zu attempts%s on %d thread(s) -> %s\n", attempts.size(),
                 shard_n > 1 ? (" (shard " + opt.shard + " of " + std::to_string(all.size()) +
                                ")").c_str()
                             : "",
                 opt.jobs, opt.out_dir.c_str());
  const BenchInputs inputs(params, attempts);
  ProgressBar bar(!opt.quiet);
  const std::vector<BenchResult> results = run_bench_attempts(
      attempts, params, inputs, opt.jobs,
      [&](int done, int total, const BenchRow& row) { bar.update(done, total, row); });

  std::vector<BenchRow> rows;
  for (const BenchResult& r : results) rows.push_back(r.row);
  BenchSummaryInfo info;
  info.command = process_command_line();
  info.machine = machine_description();
  info.attempts_total = static_cast<int>(all.size());
  info.shard = shard_n > 1 ? opt.shard : "";
  info.tests = params.tests;
  if (!opt.no_sheets)
    info.sheets = write_contact_sheets(results, inputs, opt.sheet_size, opt.out_dir, opt.quiet);
  nlohmann::json meta = {{"format", "cordgrasp-bench"},
                         {"format_version", 1},
                         {"cordgrasp_version", version()},
                         {"command", info.command},
                         {"machine", info.machine},
                         {"parameters", bench_params_to_json(params)},
                         {"attempts_total", all.size()},
                         {"attempts", rows.size()},
                         {"shard", shard_n > 1 ? nlohmann::json(opt.shard) : nlohmann::json()}};
  write_bench_outputs(opt.out_dir, rows, meta, info);

  int ok = 0, errors = 0;
  for (const BenchRow& r : rows) {
    ok += r.status == "ok";
    errors += r.status == "error";
  }
  std::printf("bench: %d/%zu attempts found a force-closure grasp, %d errors -> %s\n", ok,
              rows.size(), errors, (fs::path(opt.out_dir) / "results.csv").string().c_str());
  if (errors > 0 && !opt.quiet)
    std::fprintf(stderr, "cordgrasp: warning: bench: %d attempt(s) failed; see the error column "
                         "of results.csv\n", errors);
  return errors > 0 && opt.strict ? 2 : 0;
}

}  // namespace


void add_bench_command(CLI::App& app) {
  auto opt = std::make_shared<BenchOptions>();
  CLI::App* cmd = app.add_subcommand(
      "bench", "Benchmark planners over objects × hands × repeats: results.csv, summary.md, "
               "contact sheets (docs/bench.md)");
  cmd->add_option("--hands", opt->hands, "Hands (names or files), comma separated")->required();
  cmd->add_option("--objects", opt->objects,
                  "Object mesh files and/or directories (their .obj/.stl/.ply/.off files)")
      ->required();
  cmd->add_option("--planners", opt->planners, "cord, generic or cord,generic")
      ->default_val("cord");
  cmd->add_option("--repeats", opt->repeats,
                  "Attempts per object, hand and planner; repeat r uses seed --seed + r")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  add_plan_job_options(cmd, opt->job);
  cmd->remove_option(cmd->get_option("--planner"));  // --planners instead
  cmd->add_option("--tests", opt->tests,
                  "Physics tests on each attempt's first grasp: lift,shake,gravity6 subset, or "
                  "none")
      ->capture_default_str();
  cmd->add_option("--cache-dir", opt->cache_dir,
                  "Directory caching convex decompositions on disk (by mesh hash)");
  cmd->add_option("--jobs,-j", opt->jobs, "Attempts run in parallel threads")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--shard", opt->shard,
                  "k/N: run only attempts whose index mod N = k-1 (join with cordgrasp merge)");
  cmd->add_flag("--no-sheets", opt->no_sheets, "No contact sheet PNGs");
  cmd->add_option("--sheet-size", opt->sheet_size, "Contact sheet tile size WxH [px]")
      ->capture_default_str();
  cmd->add_flag("--strict", opt->strict, "Exit 2 when any attempt is an error row");
  cmd->add_flag("--quiet,-q", opt->quiet, "No progress on stderr");
  cmd->add_option("--out-dir", opt->out_dir, "Output directory (created)")->required();
  cmd->callback([opt]() {
    const int code = run_bench(*opt);
    if (code != 0) throw CLI::RuntimeError(code);
  });
}

}  // namespace cordgrasp::cli
