// Physics validation speed (docs/physics.md §6): close + lift + shake of one planned grasp, one
// thread. Target: ≤ 0.3 s for the default SAH-like hand on a 3000-triangle object (counter
// realtime_factor: simulated seconds per CPU second). Run:
//   build/tools/cordgrasp-microbench --benchmark_filter=Validate
//     --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <exception>

#include "cordgrasp/collision/bullet_hand_collider.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/kinematics.h"
#include "cordgrasp/core/object_meshes.h"
#include "cordgrasp/core/plan_generic_grasps.h"
#include "cordgrasp/core/shapes.h"
#include "cordgrasp/sim/convex_decomposition.h"
#include "cordgrasp/sim/validate_grasp.h"

namespace {

using namespace cordgrasp;

/// First force-closure grasp of the seeded generic planner (deterministic).
Grasp planned_grasp(const Mesh& mesh, const HandModel& hand) {
  auto collider = make_bullet_hand_collider(hand, mesh);
  PlanParams params;
  params.grasps = 1;
  params.seed = 1;
  params.time_limit_s = 30.0;
  const PlanResult plan = plan_generic_grasps(mesh, hand, *collider, params);
  return plan.grasps.empty() ? Grasp{} : plan.grasps.front();
}

void validate_benchmark(benchmark::State& state, const HandModel& hand, const Mesh& mesh,
                        const SimParams& params) {
  const Grasp grasp = planned_grasp(mesh, hand);
  if (grasp.q.size() == 0) {
    state.SkipWithError("no force-closure grasp planned");
    return;
  }
  const SimTests close_lift_shake{true, true, false};
  validate_grasp(mesh, hand, grasp, params, close_lift_shake);  // warms the HACD cache
  int steps = 0;
  double simulated_s = 0.0;
  SimResult r;
  for (auto _ : state) {
    r = validate_grasp(mesh, hand, grasp, params, close_lift_shake);
    steps = 0;
    simulated_s = 0.0;
    for (const PhaseResult& p : r.phases) {
      steps += p.steps;
      simulated_s += p.sim_time_s;
    }
    benchmark::DoNotOptimize(r.outcome);
  }
  state.counters["steps"] = steps;
  // Simulated seconds per CPU second. A grasp that fails stops early, so the time per grasp
  // varies with the outcome; this does not. The thorough close + lift + shake protocol is
  // ~8.9 s simulated, the quick one ≤ 4.2 s.
  state.counters["realtime_factor"] =
      benchmark::Counter(simulated_s, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["held"] = r.held() ? 1 : 0;
  if (const PhaseResult* shake = r.phase("shake"))
    state.counters["shake_mm"] = 1e3 * shake->translation_m;
  state.counters["triangles"] = static_cast<double>(mesh.triangles.size());
}

/// validate_benchmark() of the default hand on the shipped mug (2976 triangles, HACD parts).
void validate_sah_mug(benchmark::State& state, const SimParams& params) {
  static const HandModel hand = load_hand("cordgrasp_sah");
  static const Mesh mesh = make_object_mesh("mug");
  validate_benchmark(state, hand, mesh, params);
}

/// The default hand on the shipped mug at the default parameters.
void BM_ValidateSahMug(benchmark::State& state) { validate_sah_mug(state, SimParams{}); }
BENCHMARK(BM_ValidateSahMug)->Unit(benchmark::kMillisecond)->Iterations(3);

/// Time step, solver iterations and contact model against speed
/// (docs/notes/2026-11-22-physics-measurements.md): the default hand on the shipped mug at
/// 1/arg0 s with arg1 iterations, compliant contacts (2e5 N/m, 400 N·s/m) when arg2 is 1, else
/// the default rigid ones (filter: SimStep).
void BM_SimStepSahMug(benchmark::State& state) {
  SimParams params;
  params.time_step_s = 1.0 / static_cast<double>(state.range(0));
  params.solver_iterations = static_cast<int>(state.range(1));
  if (state.range(2) == 1) {
    params.contact_stiffness_Npm = 2e5;
    params.contact_damping_Nspm = 400.0;
  }
  validate_sah_mug(state, params);
}
BENCHMARK(BM_SimStepSahMug)
    ->ArgNames({"per_s", "iterations", "compliant"})
    ->Args({240, 20, 1})
    ->Args({480, 20, 1})
    ->Args({480, 20, 0})
    ->Args({960, 20, 0})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(2);

/// Object hulls and solver settings against speed (docs/notes/2026-11-22-physics-measurements.md):
/// the default hand on the shipped mug with part hulls of at most arg0 vertices, arg1 solver
/// iterations and articulated warmstarting when arg2 is 1 (filter: SolverSahMug).
void BM_SolverSahMug(benchmark::State& state) {
  SimParams params;
  params.decomposition.max_hull_vertices = static_cast<int>(state.range(0));
  params.solver_iterations = static_cast<int>(state.range(1));
  params.articulated_warmstarting = state.range(2) == 1;
  validate_sah_mug(state, params);
}
BENCHMARK(BM_SolverSahMug)
    ->ArgNames({"hull_vertices", "iterations", "warmstart"})
    ->Args({64, 50, 0})
    ->Args({64, 20, 0})
    ->Args({64, 20, 1})
    ->Args({32, 20, 0})
    ->Args({64, 10, 0})
    ->Args({64, 10, 1})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(2);

/// Quick against thorough protocol (SimParams presets): hand `hand_name` on the shipped mug,
/// CPU time per grasp; with `mu` > 0 the grasp's friction, e.g. low enough to fail (filter:
/// Protocol). Target: quick ≤ 0.3 s per held grasp and ≥ 5× less than thorough, ≤ 0.1 s for
/// a failing grasp.
void BM_ProtocolMug(benchmark::State& state, const char* hand_name, Protocol protocol,
                    double mu) {
  HandModel hand;
  try {
    hand = load_hand(hand_name);  // schunk_sah needs ../shared/data beside the source tree
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  static const Mesh mesh = make_object_mesh("mug");
  SimParams params = sim_params_for(protocol);
  if (mu > 0.0) params.contact.mu = mu;
  validate_benchmark(state, hand, mesh, params);
}
/// Friction low enough for the mug to slip out of either hand.
constexpr double kSlipperyMu = 0.05;
BENCHMARK_CAPTURE(BM_ProtocolMug, cordgrasp_sah_quick, "cordgrasp_sah", Protocol::kQuick, 0.0)
    ->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK_CAPTURE(BM_ProtocolMug, cordgrasp_sah_thorough, "cordgrasp_sah", Protocol::kThorough,
                  0.0)
    ->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK_CAPTURE(BM_ProtocolMug, schunk_sah_quick, "schunk_sah", Protocol::kQuick, 0.0)
    ->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK_CAPTURE(BM_ProtocolMug, schunk_sah_thorough, "schunk_sah", Protocol::kThorough, 0.0)
    ->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK_CAPTURE(BM_ProtocolMug, cordgrasp_sah_standard, "cordgrasp_sah", Protocol::kStandard,
                  0.0)
    ->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK_CAPTURE(BM_ProtocolMug, schunk_sah_standard, "schunk_sah", Protocol::kStandard, 0.0)
    ->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK_CAPTURE(BM_ProtocolMug, cordgrasp_sah_slippery_standard, "cordgrasp_sah",
                  Protocol::kStandard, kSlipperyMu)
    ->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK_CAPTURE(BM_ProtocolMug, cordgrasp_sah_slippery_quick, "cordgrasp_sah",
                  Protocol::kQuick, kSlipperyMu)
    ->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK_CAPTURE(BM_ProtocolMug, cordgrasp_sah_slippery_thorough, "cordgrasp_sah",
                  Protocol::kThorough, kSlipperyMu)
    ->Unit(benchmark::kMillisecond)->Iterations(2);

/// The default hand on the shipped bottle (2880 triangles).
void BM_ValidateSahBottle(benchmark::State& state) {
  static const HandModel hand = load_hand("cordgrasp_sah");
  static const Mesh mesh = make_object_mesh("bottle");
  validate_benchmark(state, hand, mesh, SimParams{});
}
BENCHMARK(BM_ValidateSahBottle)->Unit(benchmark::kMillisecond)->Iterations(3);

/// The parallel gripper pinching a 5 cm box (a single hull).
void BM_ValidateGripperBox(benchmark::State& state) {
  static const HandModel hand = load_hand("parallel_gripper");
  static const Mesh mesh = make_box_mesh(Eigen::Vector3d::Constant(0.05));
  Grasp grasp;
  grasp.X_OG.linear() = Eigen::Vector3d(1, -1, -1).asDiagonal();
  Eigen::VectorXd q = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(hand.joints.size()));
  Eigen::VectorXd q0 = q;
  q[find_joint(hand, "left_finger_joint")] = 0.025;
  q0[find_joint(hand, "left_finger_joint")] = 0.05;
  grasp.q = apply_couplings(hand, q);
  grasp.q_preshape = apply_couplings(hand, q0);
  grasp.X_OB = root_pose_for_gcp(hand, grasp.q, grasp.X_OG);
  const SimTests close_lift_shake{true, true, false};
  for (auto _ : state)
    benchmark::DoNotOptimize(validate_grasp(mesh, hand, grasp, SimParams{}, close_lift_shake));
}
BENCHMARK(BM_ValidateGripperBox)->Unit(benchmark::kMillisecond)->Iterations(3);

/// HACD decomposition of the shipped mug (uncached).
void BM_DecomposeMug(benchmark::State& state) {
  static const Mesh mesh = make_object_mesh("mug");
  for (auto _ : state)
    benchmark::DoNotOptimize(convex_decomposition(mesh, DecompositionParams{}).parts.size());
}
BENCHMARK(BM_DecomposeMug)->Unit(benchmark::kMillisecond)->Iterations(2);

}  // namespace
