// Skewness α (docs/algorithm.md §9).
#include "cordgrasp/core/skewness.h"

#include <gtest/gtest.h>

#include <cmath>

#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/core/shapes.h"

namespace cordgrasp {
namespace {

constexpr double kAngleTol_rad = 1e-9;
constexpr double kDeg = M_PI / 180.0;

// Palm axis at angle δ from `axis`, rotated about a direction perpendicular to it.
Eigen::Vector3d tilted(const Eigen::Vector3d& axis, double delta_rad) {
  Eigen::Vector3d perp = axis.unitOrthogonal();
  return Eigen::AngleAxisd(delta_rad, perp) * axis;
}

TEST(Skewness, MatchesFormulaOnConstructedPalmAxes) {
  // Long cylinder: its largest principal axis is z.
  const Eigen::Vector3d principal = principal_axes(make_cylinder_mesh(0.02, 0.3)).axes.col(0);
  ASSERT_NEAR(std::abs(principal.z()), 1.0, 1e-9);
  struct Case {
    double delta_deg, alpha_deg;
  };
  for (const Case c : {Case{0, 0}, Case{30, 30}, Case{45, 45}, Case{90, 0}, Case{60, 30},
                       Case{120, 30}, Case{135, 45}, Case{180, 0}}) {
    const Eigen::Vector3d palm = tilted(principal, c.delta_deg * kDeg);
    EXPECT_NEAR(skewness_alpha_rad(palm, principal), c.alpha_deg * kDeg, kAngleTol_rad)
        << "delta " << c.delta_deg;
  }
}

TEST(Skewness, IgnoresAxisSignAndLength) {
  const Eigen::Vector3d a(0.0, 0.0, 2.0);
  const Eigen::Vector3d palm = 3.0 * tilted(Eigen::Vector3d::UnitZ(), 30 * kDeg);
  EXPECT_NEAR(skewness_alpha_rad(palm, a), skewness_alpha_rad(-palm, a), kAngleTol_rad);
  EXPECT_NEAR(skewness_alpha_rad(palm, a), 30 * kDeg, kAngleTol_rad);
}

TEST(Skewness, ZeroAxisGivesZero) {
  EXPECT_EQ(skewness_alpha_rad(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()), 0.0);
}

}  // namespace
}  // namespace cordgrasp
