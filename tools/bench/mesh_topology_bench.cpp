// Micro-benchmarks of topology counts, closed volume, convex hull and the object generator.
#include <benchmark/benchmark.h>

#include "cordgrasp/core/convex_hull_volume.h"
#include "cordgrasp/core/mesh_topology.h"
#include "cordgrasp/core/mesh_volume.h"
#include "cordgrasp/core/object_meshes.h"

namespace {

const cordgrasp::Mesh& shipped_mug() {
  static const cordgrasp::Mesh mug = cordgrasp::make_mug_object();  // 2976 triangles
  return mug;
}

void BM_MeshTopologyMug(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(cordgrasp::mesh_topology(shipped_mug()));
}
BENCHMARK(BM_MeshTopologyMug)->Unit(benchmark::kMicrosecond);

void BM_ClosedMeshVolumeMug(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(cordgrasp::closed_mesh_volume(shipped_mug()));
}
BENCHMARK(BM_ClosedMeshVolumeMug)->Unit(benchmark::kMicrosecond);

void BM_ConvexHullVolumeMug(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(cordgrasp::convex_hull_volume(shipped_mug()));
}
BENCHMARK(BM_ConvexHullVolumeMug)->Unit(benchmark::kMicrosecond);

void BM_GenerateAllObjects(benchmark::State& state) {
  for (auto _ : state)
    for (const auto& name : cordgrasp::shipped_object_names())
      benchmark::DoNotOptimize(cordgrasp::make_object_mesh(name));
}
BENCHMARK(BM_GenerateAllObjects)->Unit(benchmark::kMillisecond);

}  // namespace
