// Camera maths: views, auto-framing, projection (no OpenGL involved).
#include "cordgrasp/render/camera.h"

#include <gtest/gtest.h>

#include <random>

namespace cordgrasp {
namespace {

constexpr double kPixelTol = 1e-6;   // [px] analytic projections
constexpr double kFitTol_px = 1e-6;  // [px] framing is exact up to rounding

std::vector<Eigen::Vector3d> random_points(std::mt19937_64& rng, int n) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Eigen::Vector3d center(3.0 * u(rng), 3.0 * u(rng), 3.0 * u(rng));
  const Eigen::Vector3d scale(0.05 + std::abs(u(rng)), 0.05 + std::abs(u(rng)),
                              0.05 + std::abs(u(rng)));
  std::vector<Eigen::Vector3d> p;
  for (int i = 0; i < n; ++i)
    p.push_back(center + Eigen::Vector3d(u(rng), u(rng), u(rng)).cwiseProduct(scale));
  return p;
}

TEST(ParseView, RoundTripsEveryNameAndRejectsOthers) {
  for (View v : {View::kIso, View::kFront, View::kSide, View::kTop, View::kApproach})
    EXPECT_EQ(parse_view(view_name(v)), v);
  EXPECT_THROW(parse_view("diagonal"), std::invalid_argument);
}

TEST(ViewDirection, NamedViewsLookWhereDocumented) {
  ViewSpec spec;
  spec.view = View::kFront;
  EXPECT_TRUE(view_direction(spec).isApprox(Eigen::Vector3d::UnitY()));
  spec.view = View::kSide;
  EXPECT_TRUE(view_direction(spec).isApprox(-Eigen::Vector3d::UnitX()));
  spec.view = View::kTop;
  EXPECT_TRUE(view_direction(spec).isApprox(-Eigen::Vector3d::UnitZ()));
  spec.view = View::kIso;
  EXPECT_TRUE(view_direction(spec).isApprox(Eigen::Vector3d(-1, 1, -1).normalized()));
  spec.view = View::kApproach;
  spec.approach_dir_W = Eigen::Vector3d(0, 0, 2);
  EXPECT_TRUE(view_direction(spec).isApprox(Eigen::Vector3d::UnitZ()));
}

TEST(ProjectToPixel, TargetProjectsToImageCentre) {
  Camera cam;
  cam.eye_W = Eigen::Vector3d(1, 2, 3);
  cam.target_W = Eigen::Vector3d(-0.5, 0.3, 0.1);
  const Eigen::Vector2d px = project_to_pixel(cam, 640, 480, cam.target_W);
  EXPECT_NEAR(px.x(), 320.0, kPixelTol);
  EXPECT_NEAR(px.y(), 240.0, kPixelTol);
}

TEST(ProjectToPixel, PerspectiveMatchesPinholeFormula) {
  Camera cam;  // looks along +y from (0, −1, 0), z up
  cam.fov_y_rad = 0.8;
  const double f_px = 240.0 / std::tan(0.4);  // focal length for a 480 px tall image
  const Eigen::Vector3d p(0.1, 1.0, -0.05);   // depth 2 m in front of the eye
  const Eigen::Vector2d px = project_to_pixel(cam, 640, 480, p);
  EXPECT_NEAR(px.x(), 320.0 + f_px * 0.1 / 2.0, kPixelTol);
  EXPECT_NEAR(px.y(), 240.0 + f_px * 0.05 / 2.0, kPixelTol);
}

// Every point lands inside the margins, and the binding image axis is filled exactly.
void expect_tight_fit(const Camera& cam, const std::vector<Eigen::Vector3d>& p, int w, int h,
                      double margin) {
  double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
  for (const auto& q : p) {
    const Eigen::Vector2d px = project_to_pixel(cam, w, h, q);
    x0 = std::min(x0, px.x());
    x1 = std::max(x1, px.x());
    y0 = std::min(y0, px.y());
    y1 = std::max(y1, px.y());
  }
  EXPECT_GE(x0, margin * w - kFitTol_px);
  EXPECT_LE(x1, (1 - margin) * w + kFitTol_px);
  EXPECT_GE(y0, margin * h - kFitTol_px);
  EXPECT_LE(y1, (1 - margin) * h + kFitTol_px);
  const bool x_tight = std::abs(x0 - margin * w) < 1e-3 && std::abs(x1 - (1 - margin) * w) < 1e-3;
  const bool y_tight = std::abs(y0 - margin * h) < 1e-3 && std::abs(y1 - (1 - margin) * h) < 1e-3;
  EXPECT_TRUE(x_tight || y_tight) << "x [" << x0 << ", " << x1 << "] y [" << y0 << ", " << y1
                                  << "]";
  // The other axis is centred.
  EXPECT_NEAR(0.5 * (x0 + x1), 0.5 * w, 1e-3);
  EXPECT_NEAR(0.5 * (y0 + y1), 0.5 * h, 1e-3);
}

TEST(FramePoints, FitsRandomPointCloudsTightlyInEveryView) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    const auto p = random_points(rng, 50);
    for (View v : {View::kIso, View::kFront, View::kSide, View::kTop, View::kApproach}) {
      for (bool ortho : {false, true}) {
        ViewSpec spec;
        spec.view = v;
        spec.approach_dir_W = Eigen::Vector3d(0.3, -0.2, -1.0);
        spec.orthographic = ortho;
        spec.margin = 0.07;
        const Camera cam = frame_points(p, spec, 4.0 / 3.0);
        SCOPED_TRACE(view_name(v) + (ortho ? " ortho" : " perspective"));
        expect_tight_fit(cam, p, 800, 600, spec.margin);
        // Every point lies between the clip planes.
        const Eigen::Vector3d axis = (cam.target_W - cam.eye_W).normalized();
        for (const auto& q : p) {
          const double d = axis.dot(q - cam.eye_W);
          EXPECT_GT(d, cam.near_m);
          EXPECT_LT(d, cam.far_m);
        }
      }
    }
  }
}

TEST(FramePoints, ThrowsOnEmptyInput) {
  EXPECT_THROW(frame_points({}, ViewSpec{}, 1.0), std::invalid_argument);
}

TEST(FramePoints, TopViewKeepsPlusYUpOnScreen) {
  const std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0.2}};
  ViewSpec spec;
  spec.view = View::kTop;
  const Camera cam = frame_points(p, spec, 1.0);
  const Eigen::Vector2d a = project_to_pixel(cam, 100, 100, {0.5, 0.0, 0.0});
  const Eigen::Vector2d b = project_to_pixel(cam, 100, 100, {0.5, 1.0, 0.0});
  const Eigen::Vector2d c = project_to_pixel(cam, 100, 100, {1.0, 0.5, 0.0});
  EXPECT_LT(b.y(), a.y());  // +y is up (smaller row)
  EXPECT_GT(c.x(), 50.0);   // +x is right
}

}  // namespace
}  // namespace cordgrasp
