// Micro-benchmarks of hand loading and forward kinematics (the finger stage calls FK per step).
#include <benchmark/benchmark.h>

#include <filesystem>

#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/kinematics.h"
#include "cordgrasp/core/palm_width.h"

namespace {

bool have_shared_data() {
  return std::filesystem::exists(std::string(CORDGRASP_SHARED_DATA_DIR) + "/hands/schunk_sah");
}

void BM_LoadHand(benchmark::State& state, const char* name, bool shared) {
  if (shared && !have_shared_data()) {
    state.SkipWithError("shared dataset absent");
    return;
  }
  for (auto _ : state) benchmark::DoNotOptimize(cordgrasp::load_hand(name));
}
BENCHMARK_CAPTURE(BM_LoadHand, cordgrasp_sah, "cordgrasp_sah", false)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LoadHand, schunk_sah, "schunk_sah", true)->Unit(benchmark::kMillisecond);

void BM_LinkPosesWithCouplings(benchmark::State& state, const char* name, bool shared) {
  if (shared && !have_shared_data()) {
    state.SkipWithError("shared dataset absent");
    return;
  }
  const cordgrasp::HandModel hand = cordgrasp::load_hand(name);
  Eigen::VectorXd q = hand.preshape;
  for (auto _ : state) {
    q[hand.actors[0].joints[0].joint] += 1e-9;  // a new configuration every call
    benchmark::DoNotOptimize(cordgrasp::link_poses(hand, cordgrasp::apply_couplings(hand, q)));
  }
}
BENCHMARK_CAPTURE(BM_LinkPosesWithCouplings, cordgrasp_sah, "cordgrasp_sah", false)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_LinkPosesWithCouplings, schunk_sah, "schunk_sah", true)
    ->Unit(benchmark::kMicrosecond);

void BM_MeasurePalmWidthSah(benchmark::State& state) {
  if (!have_shared_data()) {
    state.SkipWithError("shared dataset absent");
    return;
  }
  const cordgrasp::HandModel hand = cordgrasp::load_hand("schunk_sah");
  for (auto _ : state) benchmark::DoNotOptimize(cordgrasp::measure_palm_width(hand));
}
BENCHMARK(BM_MeasurePalmWidthSah)->Unit(benchmark::kMicrosecond);

}  // namespace
