// The cord planner with the Schunk SAH on the shared KIT and YCB objects (label `dataset`).
#include <gtest/gtest.h>

#include "cordgrasp/collision/bullet_hand_collider.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/plan_cord_grasps.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

void expect_force_closure_on_every_object(const std::string& folder) {
  const HandModel hand = load_hand("schunk_sah");
  const auto objects = test::files_in(test::shared_data_dir() + "/objects/" + folder, ".obj");
  ASSERT_FALSE(objects.empty()) << folder;
  CordParams cord;
  PlanParams params;
  params.time_limit_s = 10.0;
  for (const std::string& path : objects) {
    const Mesh mesh = load_mesh(path);
    auto collider = make_bullet_hand_collider(hand, mesh);
    const PlanResult plan = plan_cord_grasps(mesh, hand, *collider, cord, params);
    ASSERT_FALSE(plan.grasps.empty())
        << path << ": " << plan.stats.regions << " regions, " << plan.stats.attempts
        << " attempts (" << plan.stats.not_force_closure << " not FC, " << plan.stats.one_contact
        << " one contact, " << plan.stats.no_contact << " no contact, " << plan.stats.cannot_retreat
        << " cannot retreat)";
    EXPECT_TRUE(plan.grasps[0].force_closure);
    EXPECT_GT(plan.grasps[0].epsilon, 0.0);
  }
}

TEST(CordPlannerDataset, FindsForceClosureOnEveryKitObjectWithSchunkSah) {
  CORDGRASP_REQUIRE_SHARED_DATA();
  expect_force_closure_on_every_object("kit");
}

TEST(CordPlannerDataset, FindsForceClosureOnEveryYcbObjectWithSchunkSah) {
  CORDGRASP_REQUIRE_SHARED_DATA();
  expect_force_closure_on_every_object("ycb");
}

}  // namespace
}  // namespace cordgrasp
