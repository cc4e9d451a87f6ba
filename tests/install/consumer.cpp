// Plans one grasp of the shipped mug with the default hand, from the installed assets.
// Prints the assets folder it used and the grasp; exits non-zero when no grasp is found.
#include <cstdio>

#include "cordgrasp/core/assets.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/jobs/plan_job.h"

int main() {
  using namespace cordgrasp;
  try {
    const std::string object_path = resolve_object_path("mug");
    const Mesh mesh = load_mesh(object_path);
    const HandModel hand = load_hand(default_hand_name());
    PlanJobParams planner;
    planner.plan.grasps = 1;
    const PlanDocument plan = plan_job(planner, mesh, object_path, hand);
    std::printf("assets %s\n", assets_dir().c_str());
    if (plan.grasps.empty()) return std::printf("no force-closure grasp\n"), 1;
    std::printf("grasp 0: epsilon %.4f, %zu contacts, hand %s\n", plan.grasps[0].epsilon,
                plan.grasps[0].contacts.size(), hand.name.c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "consumer: %s\n", e.what());
    return 1;
  }
}
