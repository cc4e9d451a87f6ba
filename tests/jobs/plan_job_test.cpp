// plan_job: the typed parameters it records are the ones it planned with, so a replay of the
// exploration from plan.json alone reproduces the regions.
#include "cordgrasp/jobs/plan_job.h"

#include <gtest/gtest.h>

#include <cmath>

#include "cordgrasp/core/explore_cords.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/plan_cord_grasps.h"
#include "cordgrasp/jobs/plan_json.h"
#include "scoped_env.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

TEST(PlanJob, ExplorationReplayedFromPlanJsonReproducesTheGraspsRegion) {
  const HandModel hand = load_hand("cordgrasp_sah");
  const std::string object = test::source_dir() + "/assets/objects/mug.obj";
  PlanJobParams p;
  p.plan.seed = 5;
  p.plan.time_limit_s = 1000.0;  // not hit: exploration stays deterministic
  p.cord.sets = 6;
  p.cord.sphere_points = 4000;       // fields the CLI does not set: the replay must read them
  p.cord.xi_max_m = 0.07;
  p.cord.perturbations_per_set = 4;
  const Mesh mesh = load_job_mesh(p, object);
  const PlanDocument plan = plan_job(p, mesh, object, hand);
  ASSERT_FALSE(plan.grasps.empty());
  ASSERT_TRUE(plan.grasps[0].region_rank.has_value());

  const PlanDocument back = plan_from_json(plan_to_json(plan, hand), hand, "plan.json");
  ASSERT_TRUE(back.cord.has_value());
  EXPECT_EQ(back.cord->sphere_points, 4000);
  EXPECT_EQ(back.cord->seed, 5u);
  const std::vector<GraspRegion> regions = explore_cords(mesh, back.palm_width_m, *back.cord);
  const std::vector<int> order = cord_region_order(regions, back.palm_width_m, *back.cord);
  const Grasp& g = plan.grasps[0];
  ASSERT_LT(*g.region_rank, static_cast<int>(order.size()));
  EXPECT_EQ(regions[order[*g.region_rank]].chi_m2, *g.chi_m2);
}

TEST(PlanJob, ContactModelIsThePlannersWithTheHandsPatchRadius) {
  const HandModel hand = load_hand("parallel_gripper");
  const std::string object = test::source_dir() + "/assets/objects/box.obj";
  PlanJobParams p;
  p.planner = PlannerKind::kGeneric;
  p.plan.quality.contact.mu = 0.3;
  p.plan.time_limit_s = 2.0;
  const PlanDocument plan = plan_job(p, load_job_mesh(p, object), object, hand);
  EXPECT_EQ(plan_contact_model(plan).mu, 0.3);
  EXPECT_EQ(plan_contact_model(plan).soft_finger_radius_m, hand.soft_finger_radius_m);
  EXPECT_FALSE(plan.cord.has_value());
}

TEST(PlannerKind, NamesRoundTripAndAnUnknownOneIsRefused) {
  for (const PlannerKind k : {PlannerKind::kCord, PlannerKind::kGeneric})
    EXPECT_EQ(parse_planner_kind(to_string(k)), k);
  EXPECT_STREQ(to_string(PlannerKind::kCord), "cord");  // plan.json and scripts use the names
  EXPECT_THROW(parse_planner_kind("magic"), std::invalid_argument);
}

TEST(MeshCacheFolder, TheVariableThenXdgThenHome) {
  using test::ScopedEnv;
  const ScopedEnv home("HOME", std::string("/home/user"));
  {
    const ScopedEnv set("CORDGRASP_MESH_CACHE", std::string("/scratch/meshes"));
    EXPECT_EQ(mesh_cache_folder(), "/scratch/meshes");
    EXPECT_EQ(job_mesh_load_options(LengthUnits::kMillimeters, 2.0).cache_folder,
              "/scratch/meshes");
  }
  {
    const ScopedEnv off("CORDGRASP_MESH_CACHE", std::string("off"));
    EXPECT_EQ(mesh_cache_folder(), "");
  }
  const ScopedEnv unset("CORDGRASP_MESH_CACHE", std::nullopt);
  {
    const ScopedEnv xdg("XDG_CACHE_HOME", std::string("/var/cache/user"));
    EXPECT_EQ(mesh_cache_folder(), "/var/cache/user/cordgrasp/meshes");
  }
  const ScopedEnv no_xdg("XDG_CACHE_HOME", std::nullopt);
  EXPECT_EQ(mesh_cache_folder(), "/home/user/.cache/cordgrasp/meshes");
}

}  // namespace
}  // namespace cordgrasp
