// The convention checks on generated hands (tools/make_hand_zoo.py, seed 1, made here): every
// draft that passes them is caught once made deliberately wrong (palm normal flipped, one
// actor's closing direction reversed).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>

#include "cordgrasp/core/draft_hand_description.h"
#include "cordgrasp/core/hand_conventions.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

namespace fs = std::filesystem;

constexpr int kHands = 30;

/// Writes the seed-1 zoo into a temporary folder and returns it.
fs::path make_zoo() {
  const fs::path dir = fs::temp_directory_path() / "cordgrasp_zoo_checks_test";
  fs::remove_all(dir);
  const std::string cmd = std::string(CORDGRASP_PYTHON) + " " + test::source_dir() +
                          "/tools/make_hand_zoo.py --out " + dir.string() + " --count " +
                          std::to_string(kHands) + " --seed 1 > /dev/null";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  return dir;
}

TEST(HandZooChecks, CatchAFlippedPalmNormalOrAReversedActorOnEveryPassingDraft) {
  const fs::path zoo = make_zoo();
  int passing = 0, mutants = 0;
  for (int i = 0; i < kHands; ++i) {
    const std::string name = "hand_" + std::string(i < 10 ? "0" : "") + std::to_string(i);
    const fs::path urdf = zoo / name / (name + ".urdf");
    ASSERT_TRUE(fs::exists(urdf)) << urdf;
    const HandDraft draft = draft_hand_description(urdf.string(), (zoo / name / "d.yaml").string());
    if (!draft.problems.empty()) continue;
    ++passing;
    const HandModel& hand = draft.hand;
    ASSERT_TRUE(hand.palm_normal.has_value()) << name;
    {  // the palm normal flipped, alone
      HandModel wrong = hand;
      wrong.palm_normal->n_L = -wrong.palm_normal->n_L;
      EXPECT_FALSE(check_hand_conventions(wrong).empty()) << name << ": palm normal flipped";
      ++mutants;
    }
    {  // the palm normal and the GCP's approach axis flipped (the draft's z follows the normal)
      HandModel wrong = hand;
      wrong.palm_normal->n_L = -wrong.palm_normal->n_L;
      wrong.gcp.X_LG.linear() =
          wrong.gcp.X_LG.linear() * Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX());
      EXPECT_FALSE(check_hand_conventions(wrong).empty())
          << name << ": palm normal and GCP z flipped";
      ++mutants;
    }
    for (size_t a = 0; a < hand.actors.size(); ++a) {  // one actor closing the wrong way
      HandModel wrong = hand;
      for (auto& e : wrong.actors[a].joints) e.direction_speed = -e.direction_speed;
      const auto problems = check_hand_conventions(wrong);
      EXPECT_FALSE(problems.empty()) << name << ": actor '" << hand.actors[a].name
                                     << "' reversed";
      ++mutants;
    }
  }
  // Most drafts pass (the floors of tests/hand_zoo), so the mutants cover every layout.
  EXPECT_GE(passing, 24);
  std::cout << passing << " of " << kHands << " drafts pass; " << mutants << " wrong drafts\n";
}

}  // namespace
}  // namespace cordgrasp
