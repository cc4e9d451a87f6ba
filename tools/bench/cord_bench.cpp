// Exploration stage benchmarks (docs/algorithm.md §5): 20 sets + local improvement, one thread,
// per shared KIT and YCB object (and the shipped objects), default hand's palm width. Targets:
// median ≤ 20 ms (KIT), ≤ 100 ms (3000-triangle YCB). Run: build/tools/cordgrasp-microbench
// --benchmark_filter=Explore
//        --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "cordgrasp/core/explore_cords.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/palm_width.h"

namespace {

namespace fs = std::filesystem;

/// W_palm of the shipped default hand (cordgrasp_sah: 0.0844 m), measured once.
double default_palm_width_m() {
  static const double w =
      cordgrasp::palm_width(cordgrasp::load_hand(cordgrasp::default_hand_name()));
  return w;
}
/// Cap per exploration: Dex-Net-scaled KIT objects narrower than the palm have no valid set
/// under the default discard rule and would otherwise run to the 30 s default cap.
constexpr double kTimeLimit_s = 2.0;

/// An object file, loaded (and scaled) on first use, outside the timed loop.
struct LazyMesh {
  std::string path;
  double scale = 1.0;
  std::unique_ptr<cordgrasp::Mesh> mesh;
  const cordgrasp::Mesh& get() {
    if (!mesh) {
      mesh = std::make_unique<cordgrasp::Mesh>(cordgrasp::load_mesh(path));
      for (auto& v : mesh->vertices) v *= scale;
    }
    return *mesh;
  }
};

void explore(benchmark::State& state, const std::shared_ptr<LazyMesh>& lazy) {
  const cordgrasp::Mesh* mesh = &lazy->get();
  const double palm_width_m = default_palm_width_m();
  cordgrasp::CordParams params;
  params.time_limit_s = kTimeLimit_s;
  cordgrasp::ExplorationStats stats;
  size_t regions = 0;
  for (auto _ : state) {
    const auto result = cordgrasp::explore_cords(*mesh, palm_width_m, params, &stats);
    regions = result.size();
    benchmark::DoNotOptimize(result.data());
  }
  state.counters["regions"] = double(regions);
  state.counters["sets"] = double(stats.sets_valid);
  state.counters["capped"] = stats.hit_time_limit ? 1.0 : 0.0;
  state.counters["triangles"] = double(mesh->triangles.size());
}

std::vector<std::string> objs(const std::string& dir) {
  std::vector<std::string> out;
  if (!fs::is_directory(dir)) return out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".obj") out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

/// Registers one benchmark per object.
bool register_explore_benchmarks() {
  const std::string root = std::string(CORDGRASP_SHARED_DATA_DIR) + "/objects/";
  struct Set {
    const char* name;
    const char* dir;
    double scale;
  };
  // KIT at Dex-Net scale (median extent 4.5 cm), KIT ×2 (≈ real size, MANIFEST), YCB.
  const std::string shipped = std::string(CORDGRASP_SOURCE_DIR) + "/assets/objects";
  for (const Set& set : {Set{"BM_ExploreKit", "kit", 1.0}, Set{"BM_ExploreKitX2", "kit", 2.0},
                         Set{"BM_ExploreYcb", "ycb", 1.0}, Set{"BM_ExploreShipped", "", 1.0}})
    for (const std::string& path : objs(*set.dir ? root + set.dir : shipped)) {
      auto lazy = std::make_shared<LazyMesh>(LazyMesh{path, set.scale, nullptr});
      const std::string name = fs::path(path).stem().string();
      benchmark::RegisterBenchmark((std::string(set.name) + "/" + name).c_str(), explore, lazy)
          ->Unit(benchmark::kMillisecond);
    }
  return true;
}

const bool kRegistered = register_explore_benchmarks();

}  // namespace
