// Grasp planner benchmarks (speed targets), Schunk SAH, one thread:
//   CordFirstFC/<set>/<object>     loaded mesh → first force-closure grasp (collider, cord
//                                  exploration, finger stage, wrench space), 2 s cap
//   GenericFirstFC/<set>/<object>  the same with the generic baseline planner
//   FingerStage/<set>/<object>     finger stage alone per region (both rolls), 20 best regions
// Counters: fc (1 = found within 2 s), attempts, regions (processed), finger_ms_per_region.
// Medians over objects: tools/bench/summarize_planner_bench.py on --benchmark_format=json.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "cordgrasp/collision/bullet_hand_collider.h"
#include "cordgrasp/core/explore_cords.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/palm_width.h"
#include "cordgrasp/core/plan_cord_grasps.h"
#include "cordgrasp/core/plan_generic_grasps.h"

namespace {

using namespace cordgrasp;

constexpr double kTimeLimit_s = 2.0;

const HandModel& sah() {
  static const HandModel hand = load_hand("schunk_sah");
  return hand;
}

const Mesh& mesh_at(const std::string& path) {
  static std::map<std::string, Mesh> cache;
  auto it = cache.find(path);
  if (it == cache.end()) it = cache.emplace(path, load_mesh(path)).first;
  return it->second;
}

PlanParams plan_params() {
  PlanParams p;
  p.time_limit_s = kTimeLimit_s;
  return p;
}

CordParams cord_params() {
  CordParams c;
  return c;
}

void report(benchmark::State& state, const PlanResult& r) {
  state.counters["fc"] = r.grasps.empty() ? 0.0 : 1.0;
  state.counters["attempts"] = r.stats.attempts;
  state.counters["regions"] = r.stats.regions_processed;
  if (r.stats.regions_processed > 0)
    state.counters["finger_ms_per_region"] = 1e3 * r.stats.finger_s / r.stats.regions_processed;
}

void BM_CordFirstFC(benchmark::State& state, const std::string& path) {
  const Mesh& mesh = mesh_at(path);
  PlanResult r;
  for (auto _ : state) {
    auto collider = make_bullet_hand_collider(sah(), mesh);
    r = plan_cord_grasps(mesh, sah(), *collider, cord_params(), plan_params());
  }
  report(state, r);
}

void BM_GenericFirstFC(benchmark::State& state, const std::string& path) {
  const Mesh& mesh = mesh_at(path);
  PlanResult r;
  for (auto _ : state) {
    auto collider = make_bullet_hand_collider(sah(), mesh);
    r = plan_generic_grasps(mesh, sah(), *collider, plan_params());
  }
  report(state, r);
}

void BM_FingerStage(benchmark::State& state, const std::string& path) {
  const Mesh& mesh = mesh_at(path);
  std::vector<GraspRegion> regions = explore_cords(mesh, palm_width(sah()), cord_params());
  if (regions.size() > 20) regions.resize(20);
  if (regions.empty()) {
    state.SkipWithError("no region");
    return;
  }
  auto collider = make_bullet_hand_collider(sah(), mesh);
  const HandSetup setup = prepare_hand(sah(), *collider);
  for (auto _ : state) {
    for (const GraspRegion& region : regions) {
      const double travel = approach_travel_m(mesh, region);
      for (bool flip : {false, true})
        benchmark::DoNotOptimize(run_finger_stage(
            sah(), setup, *collider, gcp_pose_for_region(region, setup.R_GH, flip), travel));
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(regions.size()));
  state.counters["ms_per_region"] = benchmark::Counter(
      1e-3 * static_cast<double>(regions.size()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// One benchmark per shared KIT and YCB object.
const bool kRegistered = [] {
  const std::string root = std::string(CORDGRASP_SHARED_DATA_DIR) + "/objects/";
  for (const std::string set : {"kit", "ycb"}) {
    if (!std::filesystem::is_directory(root + set)) continue;
    std::vector<std::string> paths;
    for (const auto& e : std::filesystem::directory_iterator(root + set))
      if (e.path().extension() == ".obj") paths.push_back(e.path().string());
    std::sort(paths.begin(), paths.end());
    for (const std::string& path : paths) {
      const std::string name = set + "/" + std::filesystem::path(path).stem().string();
      benchmark::RegisterBenchmark(("CordFirstFC/" + name).c_str(), BM_CordFirstFC, path)
          ->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark(("GenericFirstFC/" + name).c_str(), BM_GenericFirstFC, path)
          ->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark(("FingerStage/" + name).c_str(), BM_FingerStage, path)
          ->Unit(benchmark::kMillisecond);
    }
  }
  return true;
}();

}  // namespace
