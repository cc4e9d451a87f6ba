#include "cordgrasp/sim/validate_grasp.h"

#include <gtest/gtest.h>

#include <iostream>

#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/shapes.h"
#include "sim_test_util.h"

namespace cordgrasp {
namespace {

constexpr double kBoxSide_m = 0.05;

void print(const SimResult& r) {
  std::cout << "outcome " << to_string(r.outcome) << " mass " << r.object.mass_kg << " shape "
            << to_string(r.object.shape) << " parts " << r.object.parts << " wall "
            << r.wall_time_s << "\n";
  for (const auto& p : r.phases)
    std::cout << "  " << p.name << ": " << to_string(p.outcome) << " [" << p.detail << "] dx "
              << p.translation_m << " rot " << p.rotation_rad << " maxdx " << p.max_translation_m
              << " contacts " << p.contact_count << "/" << p.max_contact_count << " pen "
              << p.max_penetration_m << " t " << p.sim_time_s << " wall " << p.wall_time_s
              << " steps " << p.steps << "\n";
}

TEST(ValidateGrasp, ParallelGripperPinchingABoxAtItsCentreHolds) {
  const HandModel hand = load_hand("parallel_gripper");
  const Mesh box = make_box_mesh(Eigen::Vector3d::Constant(kBoxSide_m));
  const Grasp grasp =
      test::top_down_pinch(hand, Eigen::Vector3d::Zero(), 0.5 * kBoxSide_m, 0.05);
  const SimResult r = validate_grasp(box, hand, grasp, SimParams{});
  print(r);
  EXPECT_EQ(r.outcome, Outcome::kHeld);
}

}  // namespace
}  // namespace cordgrasp
