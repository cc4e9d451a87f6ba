// Fuzz target: bytes as plan.json -> read_plan_json -> plan_from_json for the shipped
// parallel gripper (the hand the seeds were planned with).
#include <cstdint>

#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/jobs/plan_json.h"
#include "fuzz_input_file.h"

using namespace cordgrasp;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const HandModel hand = load_hand("parallel_gripper");
  const fuzz::FuzzInputFile file("plan.json", data, size);
  fuzz::expect_input_errors([&] {
    const nlohmann::json plan = read_plan_json(file.path());
    plan_hand_path(plan);
    plan_object_path(plan);
    plan_from_json(plan, hand, file.path());
  });
  return 0;
}
