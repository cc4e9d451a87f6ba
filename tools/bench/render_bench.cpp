// Micro-benchmarks of offscreen rendering (OSMesa llvmpipe): the target is a
// 1024×768 anti-aliased snapshot of the SAH hand (visual meshes, ~25k triangles) with a
// 3000-triangle object in ≤ 0.3 s.
// Run: build/tools/cordgrasp-microbench --benchmark_filter='Render|Png'
//        --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <memory>

#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/kinematics.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/render/animation.h"
#include "cordgrasp/render/png_io.h"
#include "cordgrasp/render/renderer.h"
#include "cordgrasp/jobs/hand_scene.h"

namespace {

using cordgrasp::Rgba;

const std::string kData = CORDGRASP_SHARED_DATA_DIR;
const std::string kSahMeshes = kData + "/hands/schunk_sah/meshes/";
const std::string kMug = kData + "/objects/ycb/025_mug.obj";

// The Schunk SAH (hands/schunk_sah via assets/hands/schunk_sah.yaml: visual meshes, 25k
// triangles) half closed around the YCB mug (3000 triangles), GCP 4 cm from the mug's centre,
// approaching along −x; one cord and a contact point as overlays; soft shadow and caption.
bool make_sah_scene(cordgrasp::Scene& scene) {
  namespace fs = std::filesystem;
  if (!fs::exists(kMug) || !fs::exists(kSahMeshes + "palmRight2.stl")) return false;
  const cordgrasp::HandModel hand = cordgrasp::load_hand("schunk_sah");
  const auto mug = std::make_shared<const cordgrasp::Mesh>(cordgrasp::load_mesh(kMug));
  const Eigen::Vector3d c = cordgrasp::mesh_bounds(*mug).center();
  cordgrasp::add_object(scene, mug);
  const Eigen::VectorXd q = cordgrasp::closing_configuration(hand, 0.5);
  Eigen::Isometry3d X_WG = Eigen::Isometry3d::Identity();  // GCP +z (approach) along −x
  X_WG.linear() << 0, 0, -1, 0, 1, 0, 1, 0, 0;
  X_WG.translation() = c + Eigen::Vector3d(0.02, 0.0, 0.0);
  const auto X_WL = cordgrasp::link_poses(hand, q, cordgrasp::root_pose_for_gcp(hand, q, X_WG));
  cordgrasp::add_hand(scene, cordgrasp::make_hand_meshes(hand), X_WL);
  cordgrasp::ScenePolyline cord;
  for (int i = 0; i <= 32; ++i) {
    const double t = M_PI * i / 32.0;
    cord.p_W.push_back(c + Eigen::Vector3d(0.05 * std::cos(t), 0.05 * std::sin(t), 0.0));
  }
  cord.width_px = 4.0;
  scene.polylines.push_back(cord);
  scene.points.push_back({c + Eigen::Vector3d(0.05, 0.0, 0.0), 0.004, Rgba(0.1, 0.1, 0.1, 1)});
  scene.ground = cordgrasp::Ground::kShadow;
  scene.caption = "025_mug · schunk_sah · cord · α = 0.12 rad · ε = 0.034";
  return true;
}

// Warm: one Renderer reused (context, shaders and mesh buffers cached), as for a series of
// snapshots. Argument: supersampling factor.
void BM_RenderSahSnapshot(benchmark::State& state) {
  cordgrasp::Scene scene;
  if (!make_sah_scene(scene)) {
    state.SkipWithError("shared dataset absent");
    return;
  }
  cordgrasp::Renderer renderer;
  cordgrasp::RenderParams params;
  params.supersample = static_cast<int>(state.range(0));
  benchmark::DoNotOptimize(renderer.render(scene, params));  // first frame compiles shaders
  for (auto _ : state) benchmark::DoNotOptimize(renderer.render(scene, params));
  state.counters["triangles"] = static_cast<double>(cordgrasp::scene_triangle_count(scene));
}
BENCHMARK(BM_RenderSahSnapshot)
    ->Arg(1)
    ->Arg(2)
    ->Arg(3)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

// Cold: a fresh Renderer per picture (OSMesa context, shader JIT, mesh upload), as for one
// `cordgrasp render` call.
void BM_RenderSahSnapshotCold(benchmark::State& state) {
  cordgrasp::Scene scene;
  if (!make_sah_scene(scene)) {
    state.SkipWithError("shared dataset absent");
    return;
  }
  cordgrasp::RenderParams params;
  for (auto _ : state) benchmark::DoNotOptimize(cordgrasp::render_scene(scene, params));
}
BENCHMARK(BM_RenderSahSnapshotCold)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

void BM_EncodePng1024x768(benchmark::State& state) {
  cordgrasp::Scene scene;
  if (!make_sah_scene(scene)) {
    state.SkipWithError("shared dataset absent");
    return;
  }
  const cordgrasp::Image image = cordgrasp::render_scene(scene);
  if (const char* path = std::getenv("CORDGRASP_BENCH_IMAGE"))  // to look at the scene
    cordgrasp::write_png(path, image);
  for (auto _ : state) benchmark::DoNotOptimize(cordgrasp::encode_png(image));
}
BENCHMARK(BM_EncodePng1024x768)->Unit(benchmark::kMillisecond);

// The picture settings of an animation frame: 640×480, no supersampling (the scene: no ground).
cordgrasp::RenderParams animation_frame_params(cordgrasp::Scene& scene) {
  scene.ground = cordgrasp::Ground::kNone;
  cordgrasp::RenderParams params;
  params.width_px = 640;
  params.height_px = 480;
  params.supersample = 1;
  return params;
}

// One frame of a physics animation (`validate --video`, run's report): the SAH scene at
// 640×480, no supersampling, rendered then added to an animated WebP. 25 frames of the mug
// moving 1 mm per frame, so the encoder sees motion. Argument: encoder effort (0 … 6).
// Target: a 3 s grasp at 25 fps (75 frames) costs no more than its physics (~0.8 s CPU).
void BM_AnimationFrame640x480(benchmark::State& state) {
  cordgrasp::Scene scene;
  if (!make_sah_scene(scene)) {
    state.SkipWithError("shared dataset absent");
    return;
  }
  cordgrasp::Renderer renderer;
  cordgrasp::RenderParams params = animation_frame_params(scene);
  params.camera = cordgrasp::frame_scenes({scene}, params);
  cordgrasp::AnimationParams anim;
  anim.effort = static_cast<int>(state.range(0));
  auto encoder = std::make_unique<cordgrasp::AnimationEncoder>(640, 480, anim);
  size_t bytes = 0;
  int frames = 0;
  for (auto _ : state) {
    scene.meshes.front().X_WM.translation().z() += 1e-3;  // the object (added first) slips
    encoder->add_frame(renderer.render(scene, params));
    if (++frames % 25 == 0) {
      bytes += encoder->finish().size();
      encoder = std::make_unique<cordgrasp::AnimationEncoder>(640, 480, anim);
      scene.meshes.front().X_WM.translation().z() -= 25e-3;
    }
  }
  if (frames >= 25)
    state.counters["bytes_per_frame"] = static_cast<double>(bytes) / (frames - frames % 25);
}
BENCHMARK(BM_AnimationFrame640x480)
    ->Arg(0)
    ->Arg(2)
    ->Arg(4)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

// Rendering alone of the frame above, to split the cost.
void BM_RenderFrame640x480(benchmark::State& state) {
  cordgrasp::Scene scene;
  if (!make_sah_scene(scene)) {
    state.SkipWithError("shared dataset absent");
    return;
  }
  cordgrasp::Renderer renderer;
  const cordgrasp::RenderParams params = animation_frame_params(scene);
  for (auto _ : state) benchmark::DoNotOptimize(renderer.render(scene, params));
}
BENCHMARK(BM_RenderFrame640x480)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
