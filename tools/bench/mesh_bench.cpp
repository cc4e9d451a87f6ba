// Micro-benchmarks of mesh loading and properties.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/mesh_properties.h"

namespace {

const std::string kMug = std::string(CORDGRASP_SHARED_DATA_DIR) + "/objects/ycb/025_mug.obj";

void BM_LoadYcbMug(benchmark::State& state) {
  if (!std::filesystem::exists(kMug)) {
    state.SkipWithError("shared dataset absent");
    return;
  }
  for (auto _ : state) benchmark::DoNotOptimize(cordgrasp::load_mesh(kMug));
}
BENCHMARK(BM_LoadYcbMug)->Unit(benchmark::kMillisecond);

void BM_PrincipalAxesYcbMug(benchmark::State& state) {
  if (!std::filesystem::exists(kMug)) {
    state.SkipWithError("shared dataset absent");
    return;
  }
  const cordgrasp::Mesh mesh = cordgrasp::load_mesh(kMug);
  for (auto _ : state) benchmark::DoNotOptimize(cordgrasp::principal_axes(mesh));
}
BENCHMARK(BM_PrincipalAxesYcbMug)->Unit(benchmark::kMicrosecond);

}  // namespace
