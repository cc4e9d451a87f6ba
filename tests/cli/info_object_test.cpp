#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "test_paths.h"

namespace cordgrasp {
namespace {

constexpr double kTol_m = 1e-9;

std::string quoted(const std::string& path) { return "\"" + path + "\""; }

struct BadInput {
  std::string file;
  std::string problem;
};

TEST(CliInfoObject, EveryBadInputExitsNonZeroWithOneLineNamingFileAndProblem) {
  const std::vector<BadInput> cases{
      {"no_such_mesh.obj", "file not found"},
      {"unknown_format.xyz", "unknown mesh format '.xyz'"},
      {"empty.obj", "empty file (0 bytes)"},
      {"only_vertices.obj", "0 triangles"},
      {"nan_coordinate.obj", "NaN/inf vertex coordinate (0, nan, 0)"},
      {"inf_coordinate.obj", "NaN/inf vertex coordinate (0, 0, inf)"},
      {"all_degenerate.obj", "all 3 triangles are degenerate"},
  };
  for (const BadInput& c : cases) {
    SCOPED_TRACE(c.file);
    const std::string path = test::test_data("meshes/" + c.file);
    const test::CommandResult r = test::run_cordgrasp("info --object " + quoted(path));
    EXPECT_NE(r.exit_code, 0);
    EXPECT_EQ(r.output.rfind("cordgrasp: error: load_mesh: '" + path + "': ", 0), 0u) << r.output;
    EXPECT_NE(r.output.find(c.problem), std::string::npos) << r.output;
    ASSERT_FALSE(r.output.empty());
    EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << "not one line: " << r.output;
  }
}

TEST(CliInfoObject, AutoUnitsPickMillimetersAndSaySo) {
  const std::string path = quoted(test::test_data("meshes/box_100mm.obj"));
  const test::CommandResult text = test::run_cordgrasp("info --object " + path + " --units auto");
  EXPECT_EQ(text.exit_code, 0) << text.output;
  EXPECT_NE(text.output.find("read as millimeters"), std::string::npos) << text.output;
  const test::CommandResult js =
      test::run_cordgrasp("info --object " + path + " --units auto --json");
  ASSERT_EQ(js.exit_code, 0) << js.output;
  const auto j = nlohmann::json::parse(js.output);
  EXPECT_TRUE(j["units_auto_chose_mm"].get<bool>());
  EXPECT_NEAR(j["size_m"][0].get<double>(), 0.1, kTol_m);
}

TEST(CliInfoObject, MillimeterUnitsScaleAndMetersDoNot) {
  const std::string path = quoted(test::test_data("meshes/box_100mm.obj"));
  const test::CommandResult mm =
      test::run_cordgrasp("info --object " + path + " --units mm --json");
  ASSERT_EQ(mm.exit_code, 0) << mm.output;
  const auto j = nlohmann::json::parse(mm.output);
  EXPECT_FALSE(j["units_auto_chose_mm"].get<bool>());
  EXPECT_EQ(j["scale_to_m"].get<double>(), 1e-3);
  EXPECT_NEAR(j["size_m"][1].get<double>(), 0.08, kTol_m);
  const test::CommandResult m = test::run_cordgrasp("info --object " + path + " --json");
  ASSERT_EQ(m.exit_code, 0) << m.output;
  EXPECT_NEAR(nlohmann::json::parse(m.output)["size_m"][1].get<double>(), 80.0, 1e-6);
  EXPECT_NE(test::run_cordgrasp("info --object " + path + " --units cm").exit_code, 0);
}

TEST(CliInfoObject, ClosedMugReportsTopologyVolumeAndHull) {
  const std::string path = quoted(test::source_dir() + "/assets/objects/mug.obj");
  const test::CommandResult js = test::run_cordgrasp("info --object " + path + " --json");
  ASSERT_EQ(js.exit_code, 0) << js.output;
  const auto j = nlohmann::json::parse(js.output);
  EXPECT_TRUE(j["topology"]["closed"].get<bool>());
  EXPECT_EQ(j["topology"]["components"].get<int>(), 2);
  EXPECT_EQ(j["topology"]["boundary_edges"].get<int>(), 0);
  const double volume = j["volume_m3"].get<double>();
  EXPECT_GT(volume, 0.0);
  EXPECT_GT(j["convex_hull_volume_m3"].get<double>(), volume);
  EXPECT_EQ(j["center_of_mass_m"].size(), 3u);
  const test::CommandResult text = test::run_cordgrasp("info --object " + path);
  ASSERT_EQ(text.exit_code, 0) << text.output;
  EXPECT_NE(text.output.find("closed (watertight), 2 components"), std::string::npos)
      << text.output;
  EXPECT_NE(text.output.find("centre of mass"), std::string::npos) << text.output;
  EXPECT_NE(text.output.find("convex-hull volume"), std::string::npos) << text.output;
}

TEST(CliInfoObject, OpenDefectiveMeshHasNoVolumeButAHull) {
  const std::string path = quoted(test::source_dir() + "/assets/objects/defective.obj");
  const test::CommandResult js = test::run_cordgrasp("info --object " + path + " --json");
  ASSERT_EQ(js.exit_code, 0) << js.output;
  const auto j = nlohmann::json::parse(js.output);
  EXPECT_FALSE(j["topology"]["closed"].get<bool>());
  EXPECT_EQ(j["topology"]["non_manifold_edges"].get<int>(), 1);
  EXPECT_TRUE(j["volume_m3"].is_null());
  EXPECT_TRUE(j["center_of_mass_m"].is_null());
  EXPECT_GT(j["convex_hull_volume_m3"].get<double>(), 0.0);
  const test::CommandResult text = test::run_cordgrasp("info --object " + path);
  EXPECT_NE(text.output.find("volume     open"), std::string::npos) << text.output;
  EXPECT_NE(text.output.find("1 non-manifold edge,"), std::string::npos) << text.output;
}

TEST(CliInfoObject, EveryFormatFileGivesValidJson) {
  const std::vector<std::string> files{"box.obj", "box_ascii.stl", "box_binary.stl", "box.ply",
                                       "box.off", "box_zup.dae",   "box.gltf"};
  for (const std::string& file : files) {
    SCOPED_TRACE(file);
    const test::CommandResult r = test::run_cordgrasp(
        "info --json --object " + quoted(test::test_data("meshes/formats/" + file)));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto j = nlohmann::json::parse(r.output);
    EXPECT_EQ(j["triangles"].get<int>(), 12);
    EXPECT_NEAR(j["volume_m3"].get<double>(), 3e-5, 1e-10);
  }
}

}  // namespace
}  // namespace cordgrasp
