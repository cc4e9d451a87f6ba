// `cordgrasp plan`: plan.json contents, summary and errors.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "test_files.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

std::string quoted(const std::string& path) { return "\"" + path + "\""; }

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() /
          ("cordgrasp_plan_test_" + std::to_string(::getpid()) + "_" + name))
      .string();
}

nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

std::string shipped_object(const std::string& name) {
  return test::source_dir() + "/assets/objects/" + name + ".obj";
}

TEST(CliPlan, CordPlanOnTheMugWritesEveryGraspField) {
  const std::string out = temp_path("mug.json");
  const test::CommandResult r =
      test::run_cordgrasp("plan --object " + quoted(shipped_object("mug")) +
                          " --grasps 2 --seed 3 --out " + quoted(out));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("force closure"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("wrote " + out), std::string::npos) << r.output;
  const nlohmann::json j = read_json(out);
  EXPECT_EQ(j["format"], "cordgrasp-plan");
  EXPECT_EQ(j["format_version"], 3);
  EXPECT_FALSE(j["cordgrasp_version"].get<std::string>().empty());
  EXPECT_EQ(j["inputs"]["hand"]["name"], "cordgrasp_sah");
  EXPECT_TRUE(std::filesystem::path(j["inputs"]["hand"]["path"].get<std::string>()).is_absolute());
  EXPECT_TRUE(
      std::filesystem::path(j["inputs"]["object"]["path"].get<std::string>()).is_absolute());
  EXPECT_EQ(j["parameters"]["planner"], "cord");
  EXPECT_EQ(j["parameters"]["seed"], 3);
  EXPECT_EQ(j["parameters"]["quality"]["contact"]["mu"], 0.5);
  EXPECT_EQ(j["parameters"]["quality"]["mode"], "textbook");
  EXPECT_GT(j["parameters"]["palm_width_m"].get<double>(), 0.0);
  EXPECT_EQ(j["parameters"]["cord"]["seed"], 3);
  ASSERT_EQ(j["grasps"].size(), 2u);
  for (const auto& g : j["grasps"]) {
    const auto& q = g["hand_pose"]["quaternion_wxyz"];
    ASSERT_EQ(q.size(), 4u);
    double norm = 0.0;
    for (const auto& c : q) norm += c.get<double>() * c.get<double>();
    EXPECT_NEAR(norm, 1.0, 1e-9);
    EXPECT_EQ(g["hand_pose"]["position_m"].size(), 3u);
    EXPECT_EQ(g["gcp_pose"]["position_m"].size(), 3u);
    EXPECT_TRUE(g["joints"].contains("index_proximal"));
    EXPECT_GE(g["contacts"].size(), 3u);
    for (const auto& c : g["contacts"]) {
      EXPECT_FALSE(c["link"].get<std::string>().empty());
      EXPECT_EQ(c["point_m"].size(), 3u);
      EXPECT_EQ(c["normal"].size(), 3u);
    }
    EXPECT_TRUE(g["force_closure"].get<bool>());
    EXPECT_GT(g["epsilon"].get<double>(), 0.0);
    EXPECT_GE(g["alpha_rad"].get<double>(), 0.0);
    EXPECT_LE(g["alpha_rad"].get<double>(), M_PI / 4 + 1e-12);
    EXPECT_TRUE(g["chi_m2"].is_number());
    EXPECT_TRUE(g["region_rank"].is_number_integer());
    EXPECT_TRUE(g["timings_s"].contains("finger"));
  }
  std::filesystem::remove(out);
}

TEST(CliPlan, GenericPlanHasNoRegionFields) {
  const std::string out = temp_path("box.json");
  const test::CommandResult r = test::run_cordgrasp(
      "plan --planner generic --object " + quoted(shipped_object("box")) + " --out " + quoted(out));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json j = read_json(out);
  EXPECT_EQ(j["parameters"]["planner"], "generic");
  ASSERT_EQ(j["grasps"].size(), 1u);
  EXPECT_TRUE(j["grasps"][0]["chi_m2"].is_null());
  EXPECT_TRUE(j["grasps"][0]["region_rank"].is_null());
  std::filesystem::remove(out);
}

TEST(CliPlan, MissingObjectExitsNonZeroWithOneLine) {
  const std::string missing = test::source_dir() + "/no_such_object.obj";
  const test::CommandResult r = test::run_cordgrasp("plan --object " + quoted(missing) + " --out " +
                                                    quoted(temp_path("x.json")));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("no_such_object.obj"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << r.output;
}

TEST(CliPlan, SettingsFileSetsThePlannerAndTheOptionsGivenWin) {
  const test::TempDir dir;
  const std::string settings =
      dir.write("settings.yaml", "planner: generic\nseed: 9\nmax_attempts: 77\n");
  const std::string out = dir.file("plan.json");
  const test::CommandResult r =
      test::run_cordgrasp("plan --object " + quoted(shipped_object("box")) + " --settings " +
                          quoted(settings) + " --seed 4 -q --out " + quoted(out));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json p = test::read_json(out).at("parameters");
  EXPECT_EQ(p.at("planner"), "generic");
  EXPECT_EQ(p.at("max_attempts"), 77);
  EXPECT_EQ(p.at("seed"), 4);  // the option, wherever it stands
  // The plan as a settings file plans the same grasps again.
  const std::string again = dir.file("again.json");
  const test::CommandResult r2 = test::run_cordgrasp(
      "plan --object " + quoted(shipped_object("box")) + " --settings " + quoted(out) +
      " -q --out " + quoted(again));
  ASSERT_EQ(r2.exit_code, 0) << r2.output;
  const nlohmann::json a = test::read_json(out), b = test::read_json(again);
  EXPECT_EQ(b.at("parameters"), a.at("parameters"));
  ASSERT_EQ(b.at("grasps").size(), a.at("grasps").size());
  for (size_t i = 0; i < a.at("grasps").size(); ++i)
    EXPECT_EQ(b["grasps"][i]["hand_pose"], a["grasps"][i]["hand_pose"]) << i;
}

TEST(CliPlan, RejectsAnUnknownQualityModeNamingTheFileAndKey) {
  const test::TempDir dir;
  const std::string settings = dir.write("quality.yaml", "quality: {mode: ferrari}\n");
  const test::CommandResult r = test::run_cordgrasp(
      "plan --object " + quoted(shipped_object("box")) + " --settings " + quoted(settings) +
      " --out " + quoted(dir.file("x.json")));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("quality.yaml': quality.mode: "), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.json")));
}

// Validated planning that simulates force-closure candidates and accepts none says so (not "no
// force-closure grasp"), with its counts; plan.json is still written.
TEST(CliPlan, ValidatedPlanningThatAcceptsNothingSaysNoneHeldNotNoForceClosure) {
  test::TempDir dir;
  const std::string heavy = dir.write("heavy.json", "{\"mass_kg\": 50}\n");
  const std::string few = dir.write("few.yaml", "max_attempts: 40\nvalidation: {budget_s: 3}\n");
  const auto r = test::run_cordgrasp(
      "plan --hand parallel_gripper --object box --validate --physics " + test::quoted(heavy) +
      " --settings " + test::quoted(few) + " --out " + test::quoted(dir.file("p.json")));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("no grasp of box with parallel_gripper accepted in physics"),
            std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("no force-closure grasp"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(" rejected early; lost as planned in close "), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("lost the object (50.000 kg) in lift or shake"), std::string::npos)
      << r.output;
  EXPECT_TRUE(std::filesystem::exists(dir.file("p.json")));
}

}  // namespace
}  // namespace cordgrasp
