// `cordgrasp hand init`: writes a loadable draft and prints one line per guess.
#include <gtest/gtest.h>

#include <filesystem>

#include "cordgrasp/core/hand_io.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

TEST(HandInitCli, WritesADraftThatLoadsAndPrintsEachGuessWithItsConfidence) {
  const std::string out =
      (std::filesystem::temp_directory_path() / "cordgrasp_hand_init_cli.yaml").string();
  std::filesystem::remove(out);
  const auto r = test::run_cordgrasp(
      "hand init --urdf " + test::test_data("hands/three_digit_claw/three_digit_claw.urdf") +
      " --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("guess thumb:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("guess palm normal:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("confidence"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("checks: every convention holds"), std::string::npos) << r.output;
  const HandModel h = load_hand(out);
  EXPECT_EQ(h.actors.size(), 3u);
  EXPECT_TRUE(h.palm_normal.has_value());
  const auto info = test::run_cordgrasp("info --hand " + out);
  EXPECT_EQ(info.exit_code, 0) << info.output;
  EXPECT_NE(info.output.find("actors:"), std::string::npos) << info.output;
}

TEST(HandInitCli, MissingUrdfIsRefusedInOneLine) {
  const auto r = test::run_cordgrasp("hand init --urdf /nonexistent.urdf --out /tmp/x.yaml");
  EXPECT_NE(r.exit_code, 0);
}

}  // namespace
}  // namespace cordgrasp
