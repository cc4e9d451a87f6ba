// Fuzz target: bytes as a hand description (YAML, docs/hand-description.md) -> load_hand. The
// shipped URDFs are copied next to it, so a description names them as `urdf:
// parallel_gripper.urdf` or `urdf: cordgrasp_sah.urdf`.
#include <cstdint>

#include "fuzz_input_file.h"
#include "fuzz_load_hand.h"

using namespace cordgrasp;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const bool copied = (fuzz::copy_shipped_urdf("parallel_gripper"),
                              fuzz::copy_shipped_urdf("cordgrasp_sah"), true);
  (void)copied;
  const fuzz::FuzzInputFile description("hand.yaml", data, size);
  fuzz::expect_input_errors([&] { fuzz::load_and_pose_hand(description.path()); });
  return 0;
}
