// `cordgrasp info --hand`: JSON and text summaries, bad input, option validation.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "test_paths.h"

namespace cordgrasp {
namespace {

using test::run_cordgrasp;
using test::test_data;

/// Runs cordgrasp and returns its stdout only (warnings on stderr are dropped), for JSON.
std::string cordgrasp_stdout(const std::string& args, int* exit_code) {
  const std::string cmd = std::string("\"") + CORDGRASP_EXE + "\" " + args + " 2>/dev/null";
  FILE* pipe = popen(cmd.c_str(), "r");
  std::string out;
  if (!pipe) return out;
  std::array<char, 4096> buf{};
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) out.append(buf.data(), n);
  const int status = pclose(pipe);
  *exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return out;
}

nlohmann::json hand_json(const std::string& hand) {
  int code = -1;
  const std::string out = cordgrasp_stdout("info --json --hand \"" + hand + "\"", &code);
  EXPECT_EQ(code, 0) << out;
  return nlohmann::json::parse(out);  // throws (fails the test) when not valid JSON
}

TEST(InfoHand, JsonOfShippedHandsHasTheirJointCounts) {
  const nlohmann::json sah = hand_json("cordgrasp_sah");
  EXPECT_EQ(sah["name"], "cordgrasp_sah");
  EXPECT_EQ(sah["joint_counts"]["revolute"], 17);
  EXPECT_EQ(sah["joint_counts"]["fixed"], 0);
  EXPECT_EQ(sah["joint_counts"]["mimic"], 4);
  EXPECT_EQ(sah["link_count"], 18);
  EXPECT_EQ(sah["dof"], 13);
  EXPECT_EQ(sah["actors"].size(), 4u);
  EXPECT_EQ(sah["gcp"]["link"], "palm");
  EXPECT_GT(sah["mass_kg"].get<double>(), 1.0);
  EXPECT_TRUE(sah["substituted_inertials"].empty());
  EXPECT_FALSE(sah["palm_width_from_description"].get<bool>());
  EXPECT_NEAR(sah["preshape"]["thumb_opposition"].get<double>(), M_PI / 2, 1e-12);

  const nlohmann::json gripper = hand_json("parallel_gripper");
  EXPECT_EQ(gripper["joint_counts"]["prismatic"], 2);
  EXPECT_EQ(gripper["dof"], 1);
  EXPECT_NEAR(gripper["palm_width_m"].get<double>(), 0.02, 1e-9);
}

TEST(InfoHand, ContinuousLimitsAreNullAndOverridesAreReported) {
  const nlohmann::json j = hand_json(test_data("hands/features/features.yaml"));
  bool found = false;
  for (const auto& joint : j["joints"])
    if (joint["name"] == "wrist roll") {
      found = true;
      EXPECT_EQ(joint["type"], "continuous");
      EXPECT_TRUE(joint["lower"].is_null());
      EXPECT_TRUE(joint["upper"].is_null());
    }
  EXPECT_TRUE(found);
  EXPECT_TRUE(j["palm_width_from_description"].get<bool>());
  EXPECT_DOUBLE_EQ(j["palm_width_m"].get<double>(), 0.07);
  EXPECT_EQ(j["substituted_inertials"].size(), 2u);
}

TEST(InfoHand, HumanSummaryNamesGcpPreshapeAndDof) {
  const auto r = run_cordgrasp("info --hand cordgrasp_sah");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* text : {"hand       cordgrasp_sah", "DOF        13", "GCP        link 'palm'",
                           "palm width", "thumb_opposition", "= 1 x 'index_middle'", "mass"})
    EXPECT_NE(r.output.find(text), std::string::npos) << text << "\n" << r.output;
}

TEST(InfoHand, BadHandFilesExitNonZeroWithTheLoaderMessage) {
  const std::pair<const char*, const char*> cases[] = {
      {"missing_urdf.yaml", "not found"},
      {"missing_mesh.yaml", "mesh file 'meshes/nope.stl' not found"},
      {"gcp_link_not_found.yaml", "GCP link 'no_such_link' not found"},
      {"preshape_unknown_joint.yaml", "unknown joint 'no_such_joint'"},
      {"inverted_limits.yaml", "inverted limits"},
      {"yaml_syntax_error.yaml", "YAML syntax error"},
      {"millimetres.yaml", "millimetres"},
  };
  for (const auto& [file, message] : cases) {
    const auto r =
        run_cordgrasp("info --hand \"" + test_data(std::string("hands/bad/") + file) + "\"");
    EXPECT_NE(r.exit_code, 0) << file;
    EXPECT_NE(r.output.find(message), std::string::npos) << file << ": " << r.output;
    // Names the file at fault: the description, or the URDF of the same stem beside it.
    const std::string stem = std::string(file).substr(0, std::string(file).find('.'));
    EXPECT_NE(r.output.find(stem + "."), std::string::npos) << "no file named: " << r.output;
  }
  const auto r = run_cordgrasp("info --hand no_such_hand");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("no_such_hand"), std::string::npos) << r.output;
}

TEST(InfoHand, NeedsExactlyOneOfObjectAndHand) {
  for (const char* args : {"info", "info --hand cordgrasp_sah --object x.obj"}) {
    const auto r = run_cordgrasp(args);
    EXPECT_NE(r.exit_code, 0) << args;
    EXPECT_NE(r.output.find("exactly one of --object"), std::string::npos) << r.output;
  }
}

struct ManifestCounts {
  const char* name;
  int fixed, revolute, prismatic;
};

TEST(InfoHandDataset, JsonOfEveryStagedHandMatchesTheManifestJointCounts) {
  CORDGRASP_REQUIRE_SHARED_DATA();
  // ../shared/data/MANIFEST.md, column "joints".
  const ManifestCounts hands[] = {
      {"schunk_sah", 22, 16, 0},   {"icub_right_hand", 6, 20, 0}, {"armar3_right_hand", 13, 11, 0},
      {"allegro_right", 4, 16, 0}, {"panda_hand", 1, 0, 2},       {"barrett_bh282", 1, 8, 0},
  };
  for (const auto& m : hands) {
    SCOPED_TRACE(m.name);
    const nlohmann::json j = hand_json(m.name);
    EXPECT_EQ(j["joint_counts"]["fixed"], m.fixed);
    EXPECT_EQ(j["joint_counts"]["revolute"], m.revolute);
    EXPECT_EQ(j["joint_counts"]["prismatic"], m.prismatic);
    EXPECT_EQ(j["joints"].size(), static_cast<size_t>(m.fixed + m.revolute + m.prismatic));
    EXPECT_GT(j["mass_kg"].get<double>(), 0.0);
    EXPECT_GT(j["palm_width_m"].get<double>(), 0.0);
  }
}

}  // namespace
}  // namespace cordgrasp
