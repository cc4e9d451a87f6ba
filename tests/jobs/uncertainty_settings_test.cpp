// Uncertainty settings (`validate --uncertainty`): the two names, partial files over the
// realistic model, a sim.json repeating its run, the YAML printed reads back, and bad files
// refused naming the file and the field.
#include "cordgrasp/jobs/uncertainty_settings.h"

#include <gtest/gtest.h>

#include <string>

#include "cordgrasp/core/error.h"
#include "test_files.h"

namespace cordgrasp {
namespace {

/// The message of the InputError that uncertainty_settings(path) throws ("" if none).
std::string refusal(const std::string& path) {
  try {
    uncertainty_settings(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(UncertaintySettings, NoneIsAllZeroAndRealisticIsTheDefaults) {
  EXPECT_TRUE(is_none(uncertainty_settings("none")));
  const UncertaintyParams r = uncertainty_settings("realistic");
  EXPECT_EQ(r.hand_offset_sigma_m, UncertaintyParams{}.hand_offset_sigma_m);
  EXPECT_EQ(r.mass_relative_spread, UncertaintyParams{}.mass_relative_spread);
}

TEST(UncertaintySettings, PartialYamlSetsItsKeysOverTheRealisticModel) {
  const test::TempDir dir;
  const std::string path =
      dir.write("u.yaml", "# friction only\nmu_relative_spread: 0.3\nhand_offset_sigma_m: 0\n");
  const UncertaintyParams u = uncertainty_settings(path);
  EXPECT_EQ(u.mu_relative_spread, 0.3);
  EXPECT_EQ(u.hand_offset_sigma_m, 0.0);
  EXPECT_EQ(u.com_offset_sigma_m, UncertaintyParams{}.com_offset_sigma_m);
}

TEST(UncertaintySettings, PrintedYamlReadsBackToTheSameModel) {
  const test::TempDir dir;
  UncertaintyParams u;
  u.hand_turn_sigma_rad = 0.01;
  u.squeeze_relative_spread = 0.05;
  const UncertaintyParams back =
      uncertainty_settings(dir.write("back.yaml", uncertainty_settings_yaml(u)));
  EXPECT_EQ(back.hand_turn_sigma_rad, 0.01);
  EXPECT_EQ(back.squeeze_relative_spread, 0.05);
  EXPECT_EQ(back.mass_relative_spread, u.mass_relative_spread);
}

TEST(UncertaintySettings, ASimJsonRepeatsTheModelOfItsRun) {
  const test::TempDir dir;
  const std::string sim = dir.write(
      "sim.json", R"({"format": "cordgrasp-sim", "parameters": {"uncertainty":
        {"hand_offset_sigma_m": 0.004, "hand_turn_sigma_rad": 0.0, "mu_relative_spread": 0.1,
         "mass_relative_spread": 0.0, "com_offset_sigma_m": 0.0,
         "squeeze_relative_spread": 0.0}}})");
  const UncertaintyParams u = uncertainty_settings(sim);
  EXPECT_EQ(u.hand_offset_sigma_m, 0.004);
  EXPECT_EQ(u.mu_relative_spread, 0.1);
  EXPECT_EQ(u.mass_relative_spread, 0.0);
  const std::string without = dir.write(
      "plain.json", R"({"format": "cordgrasp-sim", "parameters": {"uncertainty": null}})");
  EXPECT_NE(refusal(without).find("parameters.uncertainty"), std::string::npos)
      << refusal(without);
}

TEST(UncertaintySettings, BadFilesAreRefusedNamingTheFileAndTheField) {
  const test::TempDir dir;
  const std::string misspelt = dir.write("misspelt.yaml", "mu_spread: 0.2\n");
  std::string why = refusal(misspelt);
  EXPECT_NE(why.find(misspelt), std::string::npos) << why;
  EXPECT_NE(why.find("'mu_spread'"), std::string::npos) << why;
  const std::string wide = dir.write("wide.json", R"({"mass_relative_spread": 1.5})");
  why = refusal(wide);
  EXPECT_NE(why.find(wide), std::string::npos) << why;
  EXPECT_NE(why.find("mass_relative_spread"), std::string::npos) << why;
  const std::string text = dir.write("text.yaml", "com_offset_sigma_m: three\n");
  why = refusal(text);
  EXPECT_NE(why.find("com_offset_sigma_m"), std::string::npos) << why;
  EXPECT_NE(why.find("expected a number"), std::string::npos) << why;
  why = refusal(dir.file("missing.yaml"));
  EXPECT_NE(why.find("missing.yaml"), std::string::npos) << why;
}

}  // namespace
}  // namespace cordgrasp
