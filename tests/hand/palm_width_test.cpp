// measure_palm_width / palm_width (docs/algorithm.md §4).
#include "cordgrasp/core/palm_width.h"

#include <gtest/gtest.h>

#include <cmath>

#include "cordgrasp/core/hand_io.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

constexpr double kTol_m = 1e-9;

TEST(MeasurePalmWidth, ParallelGripperIsItsPadWidth) {
  // One non-thumb finger; the lateral axis is perpendicular to the opening: the finger's width.
  EXPECT_NEAR(measure_palm_width(load_hand("parallel_gripper")), 0.020, kTol_m);
}

TEST(MeasurePalmWidth, SahModelIsFingerSpanPlusOneFingerWidth) {
  // Outer fingers 6 cm apart (centre lines), 2 cm wide: 8 cm. The thumb sits 1.5 cm off the
  // middle finger's plane, which tilts the opposition direction a few degrees, so the measured
  // span is slightly larger, never smaller.
  const double w = measure_palm_width(load_hand("cordgrasp_sah"));
  EXPECT_GE(w, 0.080 - kTol_m);
  EXPECT_LT(w, 0.090);
}

TEST(MeasurePalmWidth, DoesNotDependOnGcpRollOrPosition) {
  HandModel h = load_hand("cordgrasp_sah");
  const double w0 = measure_palm_width(h);
  h.gcp.X_LG.rotate(Eigen::AngleAxisd(1.3, Eigen::Vector3d::UnitZ()));
  h.gcp.X_LG.translate(Eigen::Vector3d(0.01, -0.02, 0.03));
  EXPECT_NEAR(measure_palm_width(h), w0, 1e-9);
}

TEST(MeasurePalmWidth, GrowsWhenTheFingersSpread) {
  HandModel h = load_hand("cordgrasp_sah");
  const double w0 = measure_palm_width(h);
  h.preshape[find_joint(h, "index_abduction")] = -0.2;  // away from the middle finger
  h.preshape[find_joint(h, "ring_abduction")] = 0.2;
  EXPECT_GT(measure_palm_width(h), w0 + 0.01);
}

TEST(PalmWidth, DescriptionOverrideWins) {
  const HandModel h = load_hand(test::test_data("hands/features/features.yaml"));
  EXPECT_DOUBLE_EQ(palm_width(h), 0.07);
  HandModel g = load_hand("parallel_gripper");
  EXPECT_DOUBLE_EQ(palm_width(g), measure_palm_width(g));
  g.palm_width_m = 0.05;
  EXPECT_DOUBLE_EQ(palm_width(g), 0.05);
}

}  // namespace
}  // namespace cordgrasp
