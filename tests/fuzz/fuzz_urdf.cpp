// Fuzz target: bytes as a hand's URDF -> load_hand (URDF import, then the hand built from the
// description of the shipped parallel gripper, whose link and joint names the seeds use).
#include <cstdint>

#include "fuzz_input_file.h"
#include "fuzz_load_hand.h"

using namespace cordgrasp;

namespace {

const char* const kDescription = R"(format: 1
name: fuzzed
urdf: hand.urdf
gcp: {link: gripper_base, xyz: [0, 0, 0.10], rpy: [0, 0, 1.5707963267948966]}
palm_normal: {link: gripper_base, axis: [0, 0, 1]}
preshape: {left_finger_joint: 0.05}
actors:
  - name: fingers
    joints: {left_finger_joint: -0.1}
thumb_links: [left_finger]
soft_finger_radius_m: 0.005
)";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string description = fuzz::write_fuzz_file("hand.yaml", kDescription);
  const fuzz::FuzzInputFile urdf("hand.urdf", data, size);
  fuzz::expect_input_errors([&] { fuzz::load_and_pose_hand(description); });
  return 0;
}
