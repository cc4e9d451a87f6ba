// Micro-benchmarks of offscreen rendering (OSMesa llvmpipe): the issue-6 target is a
// 1024×768 anti-aliased snapshot of the SAH hand (visual meshes, ~25k triangles) with a
// 3000-triangle object in ≤ 0.3 s.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <memory>

#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/render/png_io.h"
#include "cordgrasp/render/renderer.h"

namespace {

using cordgrasp::Rgba;

const std::string kData = CORDGRASP_SHARED_DATA_DIR;
const std::string kSahMeshes = kData + "/hands/schunk_sah/meshes/";
const std::string kMug = kData + "/objects/ycb/025_mug.obj";

// URDF <origin xyz rpy> as a transform: R = Rz(yaw)·Ry(pitch)·Rx(roll).
Eigen::Isometry3d origin(double x, double y, double z, double roll, double pitch, double yaw) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
                   .toRotationMatrix();
  X.translation() = Eigen::Vector3d(x, y, z);
  return X;
}

Eigen::Isometry3d rot_z(double q) {
  return Eigen::Isometry3d(Eigen::AngleAxisd(q, Eigen::Vector3d::UnitZ()));
}

// The SAH visual meshes (palm, thumb base, 4 × 4 finger links ≈ 25k triangles) posed by the
// joint origins of hands/schunk_sah/schunk_sah_right.urdf (hand-coded here, fingers flexed
// 0.5 rad per joint) above the YCB mug (3000 triangles), with a cord and a contact point.
bool make_sah_scene(cordgrasp::Scene& scene) {
  namespace fs = std::filesystem;
  if (!fs::exists(kMug) || !fs::exists(kSahMeshes + "palmRight2.stl")) return false;
  const auto load = [](const std::string& name) {
    return std::make_shared<const cordgrasp::Mesh>(cordgrasp::load_mesh(kSahMeshes + name));
  };
  const auto mug = std::make_shared<const cordgrasp::Mesh>(cordgrasp::load_mesh(kMug));
  const auto palm = load("palmRight2.stl"), thumb_base = load("thumbBaseRight.stl");
  const auto base = load("fingerBase.stl"), prox = load("fingerPhaProx.stl");
  const auto mid = load("fingerPhaMid.stl"), dist = load("fingerPhaDist.stl");
  const Eigen::Vector3d c = cordgrasp::mesh_bounds(*mug).center();
  add_mesh(scene, mug, Eigen::Isometry3d::Identity(), Rgba(0.72, 0.72, 0.72, 1.0));
  // Palm above the mug, fingers pointing down along −z, palm facing −x toward the mug side.
  const Eigen::Isometry3d X_WP = origin(c.x() + 0.075, c.y(), c.z() + 0.19, 0.0, M_PI, 0.0);
  const Rgba palm_rgba(0.33, 0.35, 0.40, 1.0);
  add_mesh(scene, palm, X_WP, palm_rgba);
  const Eigen::Isometry3d X_WT = X_WP * origin(-0.003, 0.0271, 0.0, -M_PI, 0.0, M_PI / 2);
  add_mesh(scene, thumb_base, X_WT, palm_rgba);
  const Rgba finger_rgba[4] = {Rgba(0.90, 0.55, 0.20, 1), Rgba(0.25, 0.50, 0.85, 1),
                               Rgba(0.30, 0.70, 0.40, 1), Rgba(0.70, 0.40, 0.75, 1)};
  const Eigen::Isometry3d finger_base[4] = {
      X_WT * origin(0.0, 0.0855, -0.10282, -3.12937535, 0.610865238, M_PI / 2),
      X_WP * origin(-0.003, 0.04025, 0.15584, 0.0, -M_PI / 2, -3.10611011),
      X_WP * origin(-0.003, 0.0, 0.16056, 0.0, -M_PI / 2, -3.10611011),
      X_WP * origin(-0.003, -0.04025, 0.15584, 0.0, -M_PI / 2, 3.10726203)};
  constexpr double kFlex = 0.5;  // [rad] on proximal, middle and distal joints
  for (int f = 0; f < 4; ++f) {
    const Eigen::Isometry3d X_B = finger_base[f];
    add_mesh(scene, base, X_B * origin(0, 0, 0, M_PI, 0, 0), finger_rgba[f]);
    const Eigen::Isometry3d X_P = X_B * origin(0, 0, 0, M_PI / 2, 0, 0) * rot_z(kFlex);
    add_mesh(scene, prox, X_P, finger_rgba[f]);
    const Eigen::Isometry3d X_M = X_P * origin(0.0678, 0, 0, 0, 0, 0) * rot_z(kFlex);
    add_mesh(scene, mid, X_M, finger_rgba[f]);
    const Eigen::Isometry3d X_D = X_M * origin(0.03, 0, 0, 0, 0, 0) * rot_z(kFlex);
    add_mesh(scene, dist, X_D * origin(0, 0, 0, 0, 0.0218166156, 0), finger_rgba[f]);
  }
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
    ->UseRealTime();

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
BENCHMARK(BM_RenderSahSnapshotCold)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_EncodePng1024x768(benchmark::State& state) {
  cordgrasp::Scene scene;
  if (!make_sah_scene(scene)) {
    state.SkipWithError("shared dataset absent");
    return;
  }
  const cordgrasp::Image image = cordgrasp::render_scene(scene);
  for (auto _ : state) benchmark::DoNotOptimize(cordgrasp::encode_png(image));
}
BENCHMARK(BM_EncodePng1024x768)->Unit(benchmark::kMillisecond);

}  // namespace
