// Fuzz target: bytes as a physics settings file (merge_physics_file) and as a planner settings
// file (merge_plan_settings_file), each as JSON and as YAML, merged over the defaults.
#include <cstdint>

#include "cordgrasp/jobs/physics_settings.h"
#include "cordgrasp/jobs/plan_settings.h"
#include "fuzz_input_file.h"

using namespace cordgrasp;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  for (const char* name : {"settings.json", "settings.yaml"}) {
    const fuzz::FuzzInputFile file(name, data, size);
    fuzz::expect_input_errors([&] {
      SimParams params;
      merge_physics_file(file.path(), &params);
      physics_settings_yaml(params);
    });
    fuzz::expect_input_errors([&] {
      PlanJobParams job;
      ValidationParams validation;
      merge_plan_settings_file(file.path(), &job, &validation);
      plan_settings_yaml(job, validation);
    });
  }
  return 0;
}
