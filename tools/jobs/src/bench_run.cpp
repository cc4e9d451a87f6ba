#include "cordgrasp/jobs/bench_run.h"

#include <filesystem>
#include <map>
#include <sstream>

#include "cordgrasp/core/error.h"
#include "cordgrasp/core/version.h"
#include "cordgrasp/jobs/hand_scene.h"
#include "cordgrasp/jobs/json_completeness.h"
#include "cordgrasp/jobs/render_options.h"
#include "cordgrasp/render/contact_sheet.h"
#include "cordgrasp/render/png_io.h"
#include "cordgrasp/render/renderer.h"
#include "cordgrasp/sim/validate_grasp.h"

namespace cordgrasp {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> split_commas(const std::vector<std::string>& items) {
  std::vector<std::string> out;
  for (const std::string& item : items) {
    std::stringstream s(item);
    for (std::string part; std::getline(s, part, ',');)
      if (!part.empty()) out.push_back(part);
  }
  return out;
}

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
                                              const std::string& out_dir,
                                              const BenchRunCallbacks& cb) {
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
    if (cb.warning) cb.warning(std::string("bench: contact sheets not rendered: ") + e.what());
  }
  return written;
}

}  // namespace

BenchRunOutcome run_bench(const BenchRunParams& opt, const BenchRunCallbacks& cb) {
  BenchParams params;
  params.hands = split_commas(opt.hands);
  for (const std::string& p : split_commas(opt.planners)) {
    try {
      params.planners.push_back(parse_planner_kind(p));
    } catch (const std::invalid_argument&) {
      throw InputError("bench: --planners: '" + p + "' is not cord or generic");
    }
  }
  params.objects = expand_object_args(opt.objects);
  params.repeats = opt.repeats;
  params.seed = opt.job.plan.seed;
  params.job = opt.job;
  params.tests = opt.tests;
  params.protocol = opt.protocol;
  params.sim_cache_dir = opt.cache_dir;
  params.physics_file = opt.validation.physics_file;  // --physics, validated or not
  if (opt.validate) params.validation = opt.validation;
  params.uncertainty = opt.validation.uncertainty;
  params.hold_test = hold_test_params(opt.validation.min_hold_probability,
                                      opt.validation.max_draws, opt.validation.trial_seed);
  if (!is_none(params.uncertainty)) {
    try {
      check_hold_test(params.uncertainty, params.hold_test);
    } catch (const std::invalid_argument& e) {
      throw InputError(std::string("bench: --uncertainty / --min-hold-probability: ") +
                       e.what());
    }
  }
  params.hand_load = opt.hand_load;
  if (params.tests != "none") (void)sim_tests_from_string(params.tests);  // fail early
  const auto [shard_k, shard_n] = opt.shard.empty() ? std::pair{1, 1} : parse_shard(opt.shard);

  const std::vector<BenchAttempt> all = bench_attempts(params);
  const std::vector<BenchAttempt> attempts = shard_attempts(all, shard_k, shard_n);
  std::error_code ec;
  if (!opt.overwrite)
    for (const std::string name : {"results.csv", "bench.json", "summary.md", "report.html"})
      if (fs::exists(fs::path(opt.out_dir) / name, ec))
        throw InputError("bench: --out-dir '" + opt.out_dir + "' holds " +
                         (name == "report.html" ? "a report.html (of a bench or a run)"
                                                : "another bench's " + name) +
                         "; give another folder, or --overwrite to replace it");
  fs::create_directories(opt.out_dir, ec);
  if (ec) throw InputError("bench: cannot create '" + opt.out_dir + "': " + ec.message());
  if (cb.note)
    cb.note("bench: " + std::to_string(attempts.size()) + " attempts" +
            (shard_n > 1 ? " (shard " + opt.shard + " of " + std::to_string(all.size()) + ")"
                         : std::string()) +
            " on " + std::to_string(opt.jobs) + " thread(s) -> " + opt.out_dir);
  const BenchInputs inputs(params, attempts);
  const std::vector<BenchResult> results =
      run_bench_attempts(attempts, params, inputs, opt.jobs, cb.progress, opt.cancel);

  std::vector<BenchRow> rows;
  std::vector<BenchResult> finished;
  for (const BenchResult& r : results)
    if (!r.interrupted) finished.push_back(r);
  for (const BenchResult& r : finished) rows.push_back(r.row);
  const std::string interrupted =
      finished.size() < results.size() ? opt.cancel.reason() : std::string();
  BenchSummaryInfo info;
  info.command = process_command_line();
  info.machine = machine_description();
  info.attempts_total = static_cast<int>(all.size());
  info.shard = shard_n > 1 ? opt.shard : "";
  info.tests = params.tests;
  info.interrupted = interrupted;
  info.attempts_asked = static_cast<int>(attempts.size());
  if (!opt.no_sheets && interrupted.empty())
    info.sheets = write_contact_sheets(finished, inputs, opt.sheet_size, opt.out_dir, cb);
  nlohmann::json meta = {{"format", "cordgrasp-bench"},
                         {"format_version", 1},
                         {"cordgrasp_version", version()},
                         {"command", info.command},
                         {"machine", info.machine},
                         {"parameters", bench_params_to_json(params)},
                         {"attempts_total", all.size()},
                         {"attempts", rows.size()},
                         {"shard", shard_n > 1 ? nlohmann::json(opt.shard) : nlohmann::json()}};
  mark_completeness(&meta, interrupted);
  write_bench_outputs(opt.out_dir, rows, meta, info);

  BenchRunOutcome out;
  out.rows = std::move(rows);
  for (const BenchRow& r : out.rows) {
    out.ok += r.status == "ok";
    out.errors += r.status == "error";
  }
  out.results_csv = (fs::path(opt.out_dir) / "results.csv").string();
  out.attempts_asked = static_cast<int>(attempts.size());
  out.interrupted = interrupted;
  return out;
}

}  // namespace cordgrasp
