// OSMesa renderer: projected areas, centroids, overlays, determinism, framing, shading.
#include "cordgrasp/render/renderer.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>

#include "cordgrasp/core/shapes.h"
#include "cordgrasp/render/backend_info.h"
#include "cordgrasp/render/text.h"
#include "image_stats.h"

namespace cordgrasp {
namespace {

using test::non_white;
using test::rgb_at;
using test::select_pixels;

constexpr double kAreaRelTol = 0.005;  // pixel-centre sampling error of straight edges
constexpr double kCentroidTol_px = 2.0;
constexpr double kWidthTol_px = 1.0;

const Rgba kBlack(0.0, 0.0, 0.0, 1.0);
const Rgba kRed(1.0, 0.0, 0.0, 1.0);
const Rgba kGreen(0.1, 0.8, 0.1, 1.0);

Scene unit_cube_scene() {
  Scene scene;
  add_mesh(scene, make_box_mesh(Eigen::Vector3d::Ones()), Eigen::Isometry3d::Identity(), kBlack,
           Shading::kUnlit);
  return scene;
}

RenderParams small_params(int w, int h, int supersample) {
  RenderParams p;
  p.width_px = w;
  p.height_px = h;
  p.supersample = supersample;
  return p;
}

bool is_dark(int r, int g, int b) { return r < 128 && g < 128 && b < 128; }
bool is_red(int r, int g, int b) { return r > 200 && g < 80 && b < 80; }
bool is_green(int r, int g, int b) { return g > r + 40 && g > b + 40; }

// Orthographic camera looking down −z from above, screen up = +y.
Camera top_camera(double height_m) {
  Camera cam;
  cam.eye_W = Eigen::Vector3d(0, 0, 10);
  cam.target_W = Eigen::Vector3d::Zero();
  cam.up_W = Eigen::Vector3d::UnitY();
  cam.orthographic = true;
  cam.ortho_height_m = height_m;
  cam.near_m = 1.0;
  cam.far_m = 20.0;
  return cam;
}

TEST(RenderCube, OrthographicIsoCoversHexagonAreaCentred) {
  // A unit cube seen along (1, −1, 1) projects to a regular hexagon of area √3 m².
  RenderParams p = small_params(400, 300, 1);
  Camera cam;
  cam.eye_W = 10.0 * Eigen::Vector3d(1, -1, 1).normalized();
  cam.orthographic = true;
  cam.ortho_height_m = 3.0;  // 100 px/m; the image is 4 m × 3 m
  cam.near_m = 1.0;
  cam.far_m = 30.0;
  p.camera = cam;
  Renderer renderer;
  const Image image = renderer.render(unit_cube_scene(), p);
  ASSERT_EQ(image.width, 400);
  ASSERT_EQ(image.height, 300);
  const auto cube = select_pixels(image, is_dark);
  const double expected = std::sqrt(3.0) / (4.0 * 3.0);
  EXPECT_NEAR(cube.count / (400.0 * 300.0), expected, kAreaRelTol * expected);
  EXPECT_NEAR(cube.centroid.x(), 200.0, kCentroidTol_px);
  EXPECT_NEAR(cube.centroid.y(), 150.0, kCentroidTol_px);
}

TEST(RenderCube, PerspectiveFrontCoversNearFaceSquareCentred) {
  // Looking along +y from 3 m, the silhouette is the near face (depth 2.5 m): a square of side
  // f/2.5 px with f = (H/2)/tan(fov/2).
  RenderParams p = small_params(400, 300, 1);
  Camera cam;
  cam.eye_W = Eigen::Vector3d(0, -3, 0);
  cam.fov_y_rad = 40.0 * M_PI / 180.0;
  cam.near_m = 0.5;
  cam.far_m = 10.0;
  p.camera = cam;
  Renderer renderer;
  const auto cube = select_pixels(renderer.render(unit_cube_scene(), p), is_dark);
  const double side_px = 150.0 / std::tan(0.5 * cam.fov_y_rad) / 2.5;
  // Axis-aligned edges: pixel-centre sampling rounds each side to a whole pixel count.
  EXPECT_NEAR(std::sqrt(static_cast<double>(cube.count)), side_px, 1.0);
  EXPECT_NEAR(cube.x_max - cube.x_min + 1, side_px, 1.0);
  EXPECT_NEAR(cube.y_max - cube.y_min + 1, side_px, 1.0);
  EXPECT_NEAR(cube.centroid.x(), 200.0, kCentroidTol_px);
  EXPECT_NEAR(cube.centroid.y(), 150.0, kCentroidTol_px);
}

TEST(RenderCube, SupersamplingAntiAliasesEdgesWithoutMovingThem) {
  RenderParams p = small_params(400, 300, 3);
  Camera cam;
  cam.eye_W = 10.0 * Eigen::Vector3d(1, -1, 1).normalized();
  cam.orthographic = true;
  cam.ortho_height_m = 3.0;
  cam.near_m = 1.0;
  cam.far_m = 30.0;
  p.camera = cam;
  Renderer renderer;
  const Image image = renderer.render(unit_cube_scene(), p);
  // The hexagon's perimeter is 6 · √(2/3) m = 490 px: most boundary pixels are partial.
  const double perimeter_px = 6.0 * std::sqrt(2.0 / 3.0) * 100.0;
  const auto partial = select_pixels(image, [](int r, int, int) { return r > 10 && r < 245; });
  EXPECT_GT(partial.count, 0.5 * perimeter_px);
  EXPECT_LT(partial.count, 2.5 * perimeter_px);
  const auto cube = select_pixels(image, is_dark);
  const double expected_px = std::sqrt(3.0) * 100.0 * 100.0;
  EXPECT_NEAR(cube.count, expected_px, 0.5 * perimeter_px);
  EXPECT_NEAR(cube.centroid.x(), 200.0, kCentroidTol_px);
  EXPECT_NEAR(cube.centroid.y(), 150.0, kCentroidTol_px);
}

TEST(RenderPolyline, AppearsWhereProjectedWithRequestedWidthAndRoundCaps) {
  Scene scene;
  ScenePolyline line;
  line.p_W = {{-0.6, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.6, 0.0, 0.0}};
  line.width_px = 8.0;
  line.rgba = kRed;
  scene.polylines.push_back(line);
  RenderParams p = small_params(200, 200, 3);
  p.camera = top_camera(2.0);  // 100 px/m, world origin at pixel (100, 100)
  Renderer renderer;
  const Image image = renderer.render(scene, p);
  const auto red = select_pixels(image, is_red);
  // Round caps add half a width at each end: 120 + 8 px long, 8 px wide.
  EXPECT_NEAR(red.x_max - red.x_min + 1, 128.0, 2.0 * kWidthTol_px);
  EXPECT_NEAR(red.y_max - red.y_min + 1, 8.0, 2.0 * kWidthTol_px);
  EXPECT_NEAR(red.centroid.x(), 100.0, kCentroidTol_px);
  EXPECT_NEAR(red.centroid.y(), 100.0, kCentroidTol_px);
  int column = 0;
  for (int y = 0; y < 200; ++y)
    column += is_red(image.pixel(70, y)[0], image.pixel(70, y)[1], image.pixel(70, y)[2]);
  EXPECT_NEAR(column, 8.0, kWidthTol_px);
  // Nothing else is drawn.
  EXPECT_LE(non_white(image).count, red.count + 2 * (128 + 8) + 8);
}

TEST(RenderPoint, SphereAppearsWhereProjectedWithItsRadius) {
  Scene scene;
  scene.points.push_back({Eigen::Vector3d(0.3, 0.5, 0.0), 0.1, kGreen});
  RenderParams p = small_params(200, 200, 3);
  p.camera = top_camera(2.0);
  Renderer renderer;
  const Image image = renderer.render(scene, p);
  const auto sphere = non_white(image);
  EXPECT_NEAR(sphere.centroid.x(), 130.0, 1.0);
  EXPECT_NEAR(sphere.centroid.y(), 50.0, 1.0);
  EXPECT_NEAR(sphere.x_max - sphere.x_min + 1, 20.0, 2.0);
  EXPECT_NEAR(sphere.count, M_PI * 10.0 * 10.0, 0.12 * M_PI * 100.0);
  EXPECT_TRUE(is_green(image.pixel(130, 50)[0], image.pixel(130, 50)[1], image.pixel(130, 50)[2]));
}

TEST(RenderArrow, SpansFromTailToTip) {
  Scene scene;
  SceneArrow arrow;
  arrow.p_W = Eigen::Vector3d(-0.5, 0.0, 0.0);
  arrow.direction_W = Eigen::Vector3d(2.0, 0.0, 0.0);
  arrow.length_m = 1.0;
  arrow.shaft_radius_m = 0.02;
  scene.arrows.push_back(arrow);
  RenderParams p = small_params(200, 200, 3);
  p.camera = top_camera(2.0);
  Renderer renderer;
  const auto drawn = non_white(renderer.render(scene, p));
  EXPECT_NEAR(drawn.x_min, 50.0, 1.0);
  EXPECT_NEAR(drawn.x_max + 1, 150.0, 1.0);
  EXPECT_NEAR(drawn.y_max - drawn.y_min + 1, 2.0 * 2.4 * 2.0, 2.0);  // head: 2.4 shaft radii
}

TEST(RenderPolyline, IsHiddenBehindOpaqueMeshUnlessOnTop) {
  Scene scene;
  add_mesh(scene, make_box_mesh(Eigen::Vector3d(0.4, 0.4, 0.2)),
           Eigen::Isometry3d(Eigen::Translation3d(0, 0, 0.5)), Rgba(0.2, 0.3, 0.9, 1.0));
  ScenePolyline line;
  line.p_W = {{-0.6, 0.0, 0.0}, {0.6, 0.0, 0.0}};
  line.width_px = 6.0;
  line.rgba = kRed;
  scene.polylines.push_back(line);
  RenderParams p = small_params(200, 200, 2);
  p.camera = top_camera(2.0);
  Renderer renderer;
  const Image hidden = renderer.render(scene, p);
  EXPECT_FALSE(
      is_red(hidden.pixel(100, 100)[0], hidden.pixel(100, 100)[1], hidden.pixel(100, 100)[2]));
  EXPECT_TRUE(is_red(hidden.pixel(40, 100)[0], hidden.pixel(40, 100)[1], hidden.pixel(40, 100)[2]));
  scene.polylines[0].on_top = true;
  const Image shown = renderer.render(scene, p);
  EXPECT_TRUE(is_red(shown.pixel(100, 100)[0], shown.pixel(100, 100)[1], shown.pixel(100, 100)[2]));
}

TEST(RenderPolyline, LyingOnASurfaceIsNotBuriedInIt) {
  // A cord lies on the object's surface: the depth offset keeps it visible.
  Scene scene;
  add_mesh(scene, make_box_mesh(Eigen::Vector3d(1.0, 1.0, 0.2)), Eigen::Isometry3d::Identity(),
           Rgba(0.7, 0.7, 0.7, 1.0));
  ScenePolyline line;
  line.p_W = {{-0.4, 0.0, 0.1}, {0.4, 0.0, 0.1}};  // on the top face
  line.width_px = 4.0;
  line.rgba = kRed;
  scene.polylines.push_back(line);
  RenderParams p = small_params(200, 200, 2);
  p.camera = top_camera(2.0);
  p.camera->eye_W = Eigen::Vector3d(0.0, -4.0, 6.0);  // oblique, not face-on
  Renderer renderer;
  const auto on_surface = select_pixels(renderer.render(scene, p), is_red);
  scene.polylines[0].on_top = true;  // never hidden: the reference
  const auto reference = select_pixels(renderer.render(scene, p), is_red);
  ASSERT_GT(reference.count, 0.6 * 80 * 4);
  EXPECT_GE(on_surface.count, 0.97 * reference.count);
}

TEST(RenderScene, SameSceneRendersIdenticallyTwiceAndAcrossRenderers) {
  Scene scene;
  add_mesh(scene, make_torus_mesh(0.05, 0.015), Eigen::Isometry3d::Identity(),
           Rgba(0.8, 0.5, 0.2, 1.0));
  add_mesh(scene, make_box_mesh(Eigen::Vector3d(0.03, 0.03, 0.06)),
           Eigen::Isometry3d(Eigen::Translation3d(0.0, 0.0, 0.05)), Rgba(0.3, 0.5, 0.8, 1.0),
           Shading::kFlat);
  ScenePolyline line;
  line.p_W = {{-0.05, 0, 0.02}, {0, 0.05, 0.03}, {0.05, 0, 0.02}};
  scene.polylines.push_back(line);
  scene.points.push_back({Eigen::Vector3d(0, 0.05, 0.03), 0.004, kGreen});
  SceneCone cone;
  cone.apex_W = Eigen::Vector3d(0.05, 0, 0.02);
  cone.axis_W = Eigen::Vector3d(1, 0, 0);
  scene.cones.push_back(cone);
  scene.ground = Ground::kShadow;
  scene.caption = "determinism · α = 0.1";
  const RenderParams p = small_params(320, 240, 2);
  Renderer a;
  const Image first = a.render(scene, p);
  const Image second = a.render(scene, p);
  EXPECT_EQ(first.rgba, second.rgba);
  Renderer b;
  EXPECT_EQ(b.render(scene, p).rgba, first.rgba);
}

TEST(RenderScene, DestroyingOneRendererLeavesAnotherIntact) {
  Scene scene;
  add_mesh(scene, make_torus_mesh(0.05, 0.015));
  scene.points.push_back({Eigen::Vector3d(0, 0, 0.02), 0.005, kGreen});
  const RenderParams p = small_params(160, 120, 1);
  auto a = std::make_unique<Renderer>();
  Renderer b;
  const Image before = b.render(scene, p);
  a->render(scene, p);  // a's objects get the same GL names as b's
  b.render(scene, p);   // b is current when a goes away
  a.reset();
  EXPECT_EQ(b.render(scene, p).rgba, before.rgba);
}

TEST(RenderScene, AutoFramingFitsSceneInsideMarginsInEveryView) {
  Scene scene;
  add_mesh(scene, make_box_mesh(Eigen::Vector3d(0.1, 0.05, 0.2)),
           Eigen::Isometry3d(Eigen::Translation3d(1.0, 2.0, 0.5)), Rgba(0.6, 0.6, 0.6, 1.0));
  add_mesh(scene, make_sphere_mesh(0.04), Eigen::Isometry3d(Eigen::Translation3d(1.1, 2.0, 0.6)),
           Rgba(0.8, 0.3, 0.3, 1.0));
  Renderer renderer;
  for (View v : {View::kIso, View::kFront, View::kSide, View::kTop, View::kApproach}) {
    SCOPED_TRACE(view_name(v));
    RenderParams p = small_params(320, 240, 2);
    p.view.view = v;
    p.view.approach_dir_W = Eigen::Vector3d(-1.0, 0.5, -0.3);
    p.view.margin = 0.05;
    const auto drawn = non_white(renderer.render(scene, p));
    ASSERT_GT(drawn.count, 0);
    EXPECT_GE(drawn.x_min, 16 - 1);
    EXPECT_LE(drawn.x_max, 320 - 16);
    EXPECT_GE(drawn.y_min, 12 - 1);
    EXPECT_LE(drawn.y_max, 240 - 12);
    const bool fills_x = drawn.x_min <= 17 && drawn.x_max >= 302;
    const bool fills_y = drawn.y_min <= 13 && drawn.y_max >= 226;
    EXPECT_TRUE(fills_x || fills_y)
        << drawn.x_min << " " << drawn.x_max << " " << drawn.y_min << " " << drawn.y_max;
  }
}

TEST(RenderShading, SmoothShadingKeepsBoxFacesFlatAcrossCreases) {
  // Crease-split normals: every face of a box is uniformly lit under directional lights and
  // an orthographic camera; averaged normals would shade a gradient across each face.
  Scene scene;
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  add_mesh(scene, make_box_mesh(Eigen::Vector3d(1.0, 1.0, 1.0)), X, Rgba(0.6, 0.6, 0.6, 1.0));
  RenderParams p = small_params(200, 200, 1);
  Camera cam;
  cam.eye_W = Eigen::Vector3d(0, -10, 0);
  cam.orthographic = true;
  cam.ortho_height_m = 2.0;
  cam.near_m = 1.0;
  cam.far_m = 20.0;
  p.camera = cam;
  Renderer renderer;
  const Image image = renderer.render(scene, p);
  // Rotated by 0.5 rad, the two visible faces span screen x ∈ [32, 78] and [78, 168] px,
  // y ∈ [50, 150] px. Sample a 3 × 3 grid inside each.
  for (const auto& xs : {std::array<int, 3>{40, 55, 70}, std::array<int, 3>{90, 125, 160}}) {
    const Eigen::Vector3d ref = rgb_at(image, xs[1], 100);
    EXPECT_LT(ref.maxCoeff(), 250.0);  // on the box
    for (int x : xs)
      for (int y : {58, 100, 142})
        EXPECT_LE((rgb_at(image, x, y) - ref).cwiseAbs().maxCoeff(), 1.0) << x << "," << y;
  }
}

TEST(RenderShading, TranslucentConeBlendsWithBackground) {
  Scene scene;
  SceneCone cone;
  cone.apex_W = Eigen::Vector3d(0, 0, 0);
  cone.axis_W = Eigen::Vector3d(0, 0, 1);
  cone.height_m = 0.5;
  cone.half_angle_rad = 0.7;
  cone.rgba = Rgba(0.9, 0.2, 0.1, 0.35);
  scene.cones.push_back(cone);
  RenderParams p = small_params(200, 200, 1);
  p.camera = top_camera(2.0);
  Renderer renderer;
  const Eigen::Vector3d c = rgb_at(renderer.render(scene, p), 110, 100);
  EXPECT_GE(c.minCoeff(), 0.6 * 255 - 2);  // at most 2 layers of 35 %: ≥ 42 % background
  EXPECT_LT(c.minCoeff(), 245);
  scene.cones[0].rgba[3] = 1.0;
  EXPECT_LT(rgb_at(renderer.render(scene, p), 110, 100).minCoeff(), 0.6 * 255 - 2);
}

TEST(RenderGround, ShadowDarkensFloorWithGreyOnly) {
  Scene scene;
  add_mesh(scene, make_box_mesh(Eigen::Vector3d(0.1, 0.1, 0.1)),
           Eigen::Isometry3d(Eigen::Translation3d(0, 0, 0.05)), Rgba(0.2, 0.4, 0.8, 1.0));
  RenderParams p = small_params(320, 240, 2);
  Renderer renderer;
  const Image plain = renderer.render(scene, p);
  scene.ground = Ground::kShadow;
  const Image shadowed = renderer.render(scene, p);
  int darkened = 0;
  for (int y = 0; y < 240; ++y)
    for (int x = 0; x < 320; ++x) {
      const Eigen::Vector3d a = rgb_at(plain, x, y), b = rgb_at(shadowed, x, y);
      if (a.minCoeff() < 255 || b.minCoeff() > 250) continue;
      ++darkened;
      EXPECT_LE(b.maxCoeff() - b.minCoeff(), 2.0) << x << "," << y;  // neutral grey
    }
  EXPECT_GT(darkened, 200);
}

TEST(RenderGround, GridDrawsGreyLinesOnTheFloor) {
  Scene scene;
  add_mesh(scene, make_box_mesh(Eigen::Vector3d(0.1, 0.1, 0.1)),
           Eigen::Isometry3d(Eigen::Translation3d(0, 0, 0.05)), Rgba(0.2, 0.4, 0.8, 1.0));
  scene.ground = Ground::kGrid;
  Renderer renderer;
  const Image image = renderer.render(scene, small_params(320, 240, 2));
  const auto grey = select_pixels(image, [](int r, int g, int b) {
    return r < 245 && r > 150 && std::abs(r - g) <= 2 && std::abs(g - b) <= 2;
  });
  EXPECT_GT(grey.count, 300);
}

TEST(RenderCaption, DrawsTextInABandUnderTheView) {
  ASSERT_TRUE(caption_font_available())
      << "caption font " << caption_font_path()
      << " absent: install fonts-dejavu-core (tools/install-deps.sh)";
  Scene scene = unit_cube_scene();
  scene.caption = "unit cube · α = 0.5 rad";
  RenderInfo info;
  Renderer renderer;
  const Image image = renderer.render(scene, small_params(320, 240, 1), &info);
  EXPECT_TRUE(info.caption_drawn);
  ASSERT_LT(info.view_height_px, 240);
  EXPECT_EQ(image.height, 240);
  int dark = 0;
  for (int y = info.view_height_px; y < 240; ++y)
    for (int x = 0; x < 320; ++x) dark += image.pixel(x, y)[0] < 128;
  EXPECT_GT(dark, 50);
}

TEST(RenderCaption, MissingFontRendersWithoutCaption) {
  ASSERT_EQ(setenv("CORDGRASP_FONT", "/nonexistent/font.ttf", 1), 0);
  Scene scene = unit_cube_scene();
  scene.caption = "no font";
  RenderInfo info;
  Renderer renderer;
  const Image image = renderer.render(scene, small_params(160, 120, 1), &info);
  unsetenv("CORDGRASP_FONT");
  EXPECT_FALSE(info.caption_drawn);
  EXPECT_EQ(info.view_height_px, 120);
  EXPECT_EQ(image.height, 120);
}

TEST(RenderScene, LeavesOutNonFiniteItemsAndFramesTheRest) {
  Scene scene = unit_cube_scene();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Eigen::Isometry3d X_bad = Eigen::Isometry3d::Identity();
  X_bad.translation().x() = nan;
  add_mesh(scene, make_box_mesh(Eigen::Vector3d::Ones()), X_bad);
  scene.points.push_back({Eigen::Vector3d(nan, 0, 0), 0.1, kGreen});
  ScenePolyline line;
  line.p_W = {{0, 0, 0}, {std::numeric_limits<double>::infinity(), 0, 0}};
  scene.polylines.push_back(line);
  RenderParams p = small_params(160, 120, 1);
  p.view.view = View::kFront;
  RenderInfo info;
  Renderer renderer;
  const Image image = renderer.render(scene, p, &info);
  EXPECT_EQ(info.dropped_items, 3);
  const Image clean = renderer.render(unit_cube_scene(), p);
  EXPECT_EQ(image.rgba, clean.rgba);
}

TEST(RenderScene, EmptySceneGivesBackgroundImage) {
  Renderer renderer;
  const Image image = renderer.render(Scene{}, small_params(64, 48, 2));
  ASSERT_EQ(image.width, 64);
  ASSERT_EQ(image.height, 48);
  EXPECT_EQ(non_white(image, 255).count, 0);
}

TEST(RenderScene, RejectsInvalidSizes) {
  Renderer renderer;
  EXPECT_THROW(renderer.render(Scene{}, small_params(0, 10, 1)), std::invalid_argument);
  EXPECT_THROW(renderer.render(Scene{}, small_params(10, 10, 9)), std::invalid_argument);
  EXPECT_THROW(renderer.render(Scene{}, small_params(10, 9000, 1)), std::invalid_argument);
}

TEST(RenderGlInfo, DescribesTheSameContextAsARenderer) {
  EXPECT_EQ(render_gl_info(), Renderer().gl_description());
}

TEST(Renderer, ReportsAnOpenGl3CoreContext) {
  Renderer renderer;
  const std::string d = renderer.gl_description();
  EXPECT_EQ(d.rfind("OpenGL ", 0), 0u) << d;
  EXPECT_GE(d[7], '3') << d;
}

}  // namespace
}  // namespace cordgrasp
