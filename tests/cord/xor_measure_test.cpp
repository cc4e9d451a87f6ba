// XOR measure χ (docs/algorithm.md §6, Eq. (1)): Clipper area identity, the convex backend, zero
// for an extrusion, and lower χ for perpendicular than oblique approaches to a long cylinder.
#include "cordgrasp/core/xor_measure.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "cord_test_util.h"
#include "cordgrasp/core/scan_cord_set.h"
#include "cordgrasp/core/xor_area.h"

namespace cordgrasp {
namespace {

using Poly2 = std::vector<Eigen::Vector2d>;
constexpr double kPalmWidth_m = 0.085;  ///< SAH-like palm (docs/algorithm.md §4)
constexpr double kPi = 3.14159265358979323846;

/// Coordinates on Clipper's 0.1 µm grid, so its integer conversion is exact.
Eigen::Vector2d on_grid(double x, double y) {
  return {std::round(x * 1e7) / 1e7, std::round(y * 1e7) / 1e7};
}

Poly2 random_convex(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-0.03, 0.03);
  Poly2 pts;
  for (int k = 0; k < 12; ++k) pts.push_back(on_grid(u(rng), u(rng)));
  return test::gift_wrap_hull(pts);
}

Poly2 random_star(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> radius(0.005, 0.03), shift(-0.01, 0.01);
  const double cx = shift(rng), cy = shift(rng);
  Poly2 poly;
  for (int k = 0; k < 14; ++k) {
    const double a = 2 * kPi * k / 14, r = radius(rng);
    poly.push_back(on_grid(cx + r * std::cos(a), cy + r * std::sin(a)));
  }
  return poly;
}

TEST(XorArea, ClipperXorMatchesAreaIdentity) {
  // Clipper rounds each computed intersection vertex to the 0.1 µm grid, independently in the
  // XOR and the intersection: a few vertices × ~3 cm edges × 0.1 µm ≈ 1e-9 m².
  constexpr double kTol_m2 = 1e-8;
  std::mt19937_64 rng(1);
  for (int k = 0; k < 300; ++k) {
    const Poly2 p = k % 2 ? random_star(rng) : random_convex(rng);
    const Poly2 q = k % 3 ? random_star(rng) : random_convex(rng);
    const double identity = polygon_area(p) + polygon_area(q) - 2.0 * intersection_area(p, q);
    EXPECT_NEAR(xor_area(p, q), identity, kTol_m2);
  }
}

TEST(XorArea, ConvexBackendMatchesClipper) {
  constexpr double kTol_m2 = 1e-8;  // Clipper rounds intersection points to 0.1 µm (see above)
  std::mt19937_64 rng(2);
  for (int k = 0; k < 300; ++k) {
    Poly2 p = random_convex(rng), q = random_convex(rng);
    if (k % 2) std::reverse(q.begin(), q.end());  // either orientation
    EXPECT_NEAR(convex_xor_area(p, q), xor_area(p, q), kTol_m2);
  }
}

TEST(XorArea, DegeneratePolygonCountsAsEmpty) {
  const Poly2 square = {{0, 0}, {0.01, 0}, {0.01, 0.01}, {0, 0.01}};
  const Poly2 segment = {{0, 0}, {0.02, 0.02}};
  EXPECT_DOUBLE_EQ(xor_area(square, segment), 1e-4);
  EXPECT_DOUBLE_EQ(xor_area(segment, square), 1e-4);
  EXPECT_DOUBLE_EQ(convex_xor_area(square, segment), 1e-4);
  EXPECT_DOUBLE_EQ(xor_area(square, square), 0.0);
}

TEST(XorMeasure, IsTheMeanXorAreaOfTheProjectedCordsAgainstTheSeed) {
  // Seed cord: 3 sides of a 1 cm square in the plane z = 0 (closed by P_l→P_r); the side cords
  // are the same square shifted by ±2 mm in x and lifted out of the plane (projection drops z).
  auto cord = [](double dx, double z) {
    return Polyline3{{0.01 + dx, 0, z}, {dx, 0, z}, {dx, 0.01, z}, {0.01 + dx, 0.01, z}};
  };
  const std::vector<Polyline3> cords = {cord(-0.002, -0.003), cord(0, 0), cord(0.002, 0.004)};
  PlaneFrame seed_plane;                        // origin 0, e1 = x, e2 = y
  const double shifted_xor = 2 * 0.002 * 0.01;  // two 2 mm × 1 cm strips
  for (XorBackend backend : {XorBackend::kClipper, XorBackend::kConvex}) {
    CordParams params;
    params.xor_backend = backend;
    EXPECT_NEAR(xor_measure(cords, seed_plane, params), shifted_xor, 1e-12);
  }
  EXPECT_THROW(xor_measure({cord(0, 0), cord(0, 0)}, seed_plane), std::invalid_argument);
}

TEST(XorMeasure, ZeroForAnExtrudedPrismScannedAlongItsExtrusion) {
  // Long prisms along z (a box and a 48-gon cylinder) and a Case I seed in a plane ⟂ z: every
  // scanned plane cuts the same profile, which projects back onto the seed plane unchanged.
  // Typical χ of real sets is 1e-5 .. 1e-3 m². Exact clipping gives rounding-level zero; Clipper
  // can flip a coordinate's 0.1 µm rounding between cords (≈ edge × 0.1 µm ≈ 1e-9 m²).
  constexpr double kZeroConvex_m2 = 1e-12, kZeroClipper_m2 = 1e-8;
  const Eigen::Vector3d p1(-0.2, 0.005, 0.002), p2(0.1, 0.12, 0.002), p3(0.1, -0.11, 0.002);
  for (const Mesh& prism :
       {make_box_mesh(Eigen::Vector3d(0.05, 0.04, 0.6)), make_cylinder_mesh(0.025, 0.6, 48)}) {
    const CordObject object = make_cord_object(prism);
    for (XorBackend backend : {XorBackend::kConvex, XorBackend::kClipper}) {
      CordParams params;
      params.xor_backend = backend;
      ScanFailure why;
      const auto region = scan_cord_set(object, p1, p2, p3, kPalmWidth_m, params, &why);
      ASSERT_TRUE(region.has_value()) << prism.name << " failure " << int(why);
      EXPECT_EQ(region->cord_case, CordCase::kI);
      EXPECT_GE(region->n, 2);
      EXPECT_LT(region->chi_m2, backend == XorBackend::kConvex ? kZeroConvex_m2 : kZeroClipper_m2)
          << prism.name << " backend " << int(backend);
    }
  }
}

TEST(XorMeasure, LongCylinderPerpendicularApproachScoresLowerThanOblique) {
  // [P] Fig. 6–7: on a long cylinder (axis z), sets approaching perpendicular to the axis (guide
  // plane ⟂ axis) have similar cords; tilting the approach towards the axis makes the scanned
  // cross-sections elongate differently, raising χ.
  const CordObject cylinder = make_cord_object(make_cylinder_mesh(0.03, 0.5, 64));
  const Eigen::Vector3d p1(-0.2, 0.004, 0.0), p2(0.1, 0.13, 0.0), p3(0.1, -0.12, 0.0);
  auto chi_at = [&](double azimuth, double tilt) {
    // Turn the seed about the axis (azimuth), then tilt its approach out of the ⟂ plane.
    const Eigen::Matrix3d r = (Eigen::AngleAxisd(azimuth, Eigen::Vector3d::UnitZ()) *
                               Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitY()))
                                  .toRotationMatrix();
    const auto region = scan_cord_set(cylinder, r * p1, r * p2, r * p3, kPalmWidth_m);
    EXPECT_TRUE(region.has_value()) << azimuth << " " << tilt;
    return region ? region->chi_m2 : 0.0;
  };
  double worst_perpendicular = 0.0, best_oblique = 1.0;
  for (int k = 0; k < 8; ++k) {
    const double azimuth = 2 * kPi * k / 8;
    worst_perpendicular = std::max(worst_perpendicular, chi_at(azimuth, 0.0));
    for (double tilt_deg : {20.0, 35.0, -30.0})
      best_oblique = std::min(best_oblique, chi_at(azimuth, tilt_deg * kPi / 180));
  }
  EXPECT_LT(worst_perpendicular, best_oblique);
  EXPECT_GT(best_oblique, 1e-6);  // clearly non-zero
}

TEST(XorMeasure, ClipperAndConvexBackendsAgreeOnScannedSets) {
  std::mt19937_64 rng(8);
  int compared = 0;
  for (const Mesh& mesh : test::test_shapes()) {
    const CordObject object = make_cord_object(mesh);
    CordParams clipper, convex;
    clipper.xor_backend = XorBackend::kClipper;
    convex.xor_backend = XorBackend::kConvex;
    for (int k = 0; k < 300; ++k) {
      const test::GuideTriangle t = test::random_guide_triangle(object, rng);
      const auto a = scan_cord_set(object, t.p1, t.p2, t.p3, 0.05, clipper);
      if (!a) continue;
      const auto b = scan_cord_set(object, t.p1, t.p2, t.p3, 0.05, convex);
      ASSERT_TRUE(b.has_value());
      EXPECT_NEAR(a->chi_m2, b->chi_m2, 1e-8) << mesh.name;  // Clipper's 0.1 µm rounding
      ++compared;
    }
  }
  EXPECT_GE(compared, 50);
}

}  // namespace
}  // namespace cordgrasp
