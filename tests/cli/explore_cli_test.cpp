// `cordgrasp explore`: prints ranked regions and writes them as JSON.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/shapes.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

namespace fs = std::filesystem;

/// A temporary directory holding a 3 cm × 16 cm bottle-like cylinder as OBJ.
struct BottleFile {
  fs::path dir =
      fs::temp_directory_path() / ("cordgrasp_explore_cli_" + std::to_string(::getpid()));
  fs::path obj = dir / "bottle.obj";
  BottleFile() {
    fs::create_directories(dir);
    save_mesh_obj(make_cylinder_mesh(0.03, 0.16, 32), obj.string());
  }
  ~BottleFile() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};

TEST(ExploreCli, PrintsRankedRegionsAndWritesJson) {
  const BottleFile file;
  const fs::path json_path = file.dir / "regions.json";
  const test::CommandResult r = test::run_cordgrasp("explore --object " + file.obj.string() +
                                                    " --palm-width-m 0.085 --sets 4 --seed 3 " +
                                                    "--json " + json_path.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("chi[mm^2]"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("explored"), std::string::npos);
  std::ifstream in(json_path);
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["seed"], 3);
  EXPECT_GE(j["stats"]["sets_valid"], 4);  // default fallback policy: 4 full sets or 8 in all
  EXPECT_LE(j["stats"]["sets_valid"], 8);
  const auto& regions = j["regions"];
  ASSERT_GE(regions.size(), 4u);
  double previous = 0.0;
  for (const auto& region : regions) {
    EXPECT_GE(region["chi_m2"].get<double>(), previous);
    previous = region["chi_m2"].get<double>();
    EXPECT_EQ(region["front_cords"].size(), 2 * region["n"].get<size_t>() + 1);
    EXPECT_EQ(region["p_l"].size(), 3u);
  }
}

TEST(ExploreCli, UsesTheDefaultHandsPalmWidthUnlessGivenOne) {
  const BottleFile file;
  const test::CommandResult r =
      test::run_cordgrasp("explore --object " + file.obj.string() + " --sets 2 --top 1");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find(std::string("hand ") + default_hand_name()), std::string::npos)
      << r.output;
  const test::CommandResult both =
      test::run_cordgrasp("explore --object " + file.obj.string() + " --hand " +
                          default_hand_name() + " --palm-width-m 0.08");
  EXPECT_NE(both.exit_code, 0);
}

TEST(ExploreCli, NamesTheMissingObjectFile) {
  const test::CommandResult r =
      test::run_cordgrasp("explore --object /nonexistent/mug.obj --palm-width-m 0.08");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("/nonexistent/mug.obj"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace cordgrasp
