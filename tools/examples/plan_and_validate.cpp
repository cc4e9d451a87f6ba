// The library in one page: load a mesh and a hand, plan grasps, check them in physics, draw
// the first one. Usage: plan_and_validate [OUT.png]   (shipped mug and default hand)
#include <cstdio>
#include <memory>

#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/assets.h"
#include "cordgrasp/jobs/hand_scene.h"
#include "cordgrasp/jobs/physics_settings.h"
#include "cordgrasp/jobs/plan_job.h"
#include "cordgrasp/jobs/validate_plan.h"
#include "cordgrasp/render/png_io.h"
#include "cordgrasp/render/renderer.h"

int main(int argc, char** argv) {
  using namespace cordgrasp;
  const std::string object_path = resolve_object_path("mug");
  const auto mesh = std::make_shared<const Mesh>(load_mesh(object_path));
  const HandModel hand = load_hand(default_hand_name());

  PlanJobParams planner;  // the cord planner with its defaults; seed 1
  planner.plan.grasps = 2;
  const PlanDocument plan = plan_job(planner, *mesh, object_path, hand);
  if (plan.grasps.empty()) return std::printf("no force-closure grasp\n"), 1;

  // The default protocol with the friction the plan was made with.
  const SimParams physics = physics_settings(plan_contact_model(plan), PhysicsChoice{});
  const SimDocument sim = validate_plan(plan, hand, *mesh, physics, sim_tests_from_string("lift"));
  for (size_t k = 0; k < sim.results.size(); ++k)
    std::printf("grasp %zu: epsilon %.4f, %s\n", k, plan.grasps[k].epsilon,
                sim_result_line(sim.results[k]).c_str());

  const Grasp& g = plan.grasps[0];
  const Scene scene = grasp_scene(hand, make_hand_meshes(hand), mesh, g,
                                  g.region ? &*g.region : nullptr);
  write_png(argc > 1 ? argv[1] : "grasp.png", render_scene(scene));
  return 0;
}
