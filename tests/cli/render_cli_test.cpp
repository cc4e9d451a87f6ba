// `cordgrasp render`: exit codes, output files and one-line errors.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "scoped_env.h"
#include "test_files.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

namespace fs = std::filesystem;

using test::png_size;
using test::quoted;
using test::TempDir;

const std::string kMug = test::source_dir() + "/assets/objects/mug.obj";

TEST(CliRender, ObjectPictureHasRequestedSize) {
  TempDir dir;
  const std::string out = (dir.path / "mug.png").string();
  const auto r =
      test::run_cordgrasp("render --object " + quoted(kMug) +
                          " --size 320x200 --view side --ground grid --out " + quoted(out));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(png_size(out), std::make_pair(320u, 200u));
  EXPECT_NE(r.output.find(out), std::string::npos) << r.output;
}

TEST(CliRender, SeveralObjectsMakeAContactSheetOfTiles) {
  TempDir dir;
  const std::string out = (dir.path / "sheet.png").string();
  const std::string box = test::source_dir() + "/assets/objects/box.obj";
  const auto r = test::run_cordgrasp("render --object " + quoted(kMug) + " --object " +
                                     quoted(box) + " --object " + quoted(box) +
                                     " --size 100x80 --no-caption --out " + quoted(out));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // 2 columns × 2 rows of 100×80 tiles with 12 px gaps, no caption bands.
  EXPECT_EQ(png_size(out), std::make_pair(12u + 2u * 112u, 12u + 2u * 92u));
}

TEST(CliRender, HandPictureAtAClosingFractionAndJointValue) {
  TempDir dir;
  const std::string out = (dir.path / "hand.png").string();
  const auto r = test::run_cordgrasp(
      "render --hand cordgrasp_sah --close 0.5 --joint index_abduction=0.2 --collision "
      "--view approach --size 160x120 --out " +
      quoted(out));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(png_size(out), std::make_pair(160u, 120u));
}

TEST(CliRender, HandOptionErrorsNameTheProblem) {
  TempDir dir;
  const std::string out = quoted((dir.path / "x.png").string());
  auto r = test::run_cordgrasp("render --hand cordgrasp_sah --joint no_such_joint=1 --out " + out);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("no joint 'no_such_joint'"), std::string::npos) << r.output;
  r = test::run_cordgrasp("render --hand cordgrasp_sah --joint index_proximal --out " + out);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("NAME=VALUE"), std::string::npos) << r.output;
  r = test::run_cordgrasp("render --hand cordgrasp_sah --no-visual --out " + out);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("--collision"), std::string::npos) << r.output;
  r = test::run_cordgrasp("render --hand cordgrasp_sah --object " + quoted(kMug) + " --out " + out);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_FALSE(fs::exists(dir.path / "x.png"));
}

// Two hand-written regions on the shipped box, in the layout of `cordgrasp explore --json`.
std::string write_regions_json(const fs::path& dir) {
  const std::string box = test::source_dir() + "/assets/objects/box.obj";
  std::string regions;
  for (int k = 0; k < 2; ++k) {
    const std::string z = std::to_string(0.02 + 0.02 * k);
    regions += std::string(k ? "," : "") + R"({"rank": )" + std::to_string(k + 1) +
               R"(, "chi_m2": 1e-5, "case": "I", "n": 1, "xi_m": 0.03,
      "from_local_improvement": false, "p1": [0.2, 0, )" +
               z + R"(], "p2": [0, 0.1, )" + z + R"(], "p3": [0, -0.1, )" + z +
               R"(], "normal": [0, 0, 1],
      "p_l": [0, 0.025, )" +
               z + R"(], "p_r": [0, -0.025, )" + z + R"(], "p_m": [0, 0, )" + z +
               R"(], "front_cords": [[[0.025, -0.025, )" + z + R"(], [0.025, 0.025, )" + z +
               R"(]], [[0.026, -0.025, )" + z + R"(], [0.026, 0.025, )" + z +
               R"(]], [[0.027, -0.025, )" + z + R"(], [0.027, 0.025, )" + z + "]]]}";
  }
  const std::string path = (dir / "regions.json").string();
  std::ofstream(path) << R"({"object": ")" << box << R"(", "regions": [)" << regions << "]}";
  return path;
}

TEST(CliRender, RegionsFromExploreJsonAsPictureOrSheet) {
  TempDir dir;
  const std::string regions = quoted(write_regions_json(dir.path));
  const std::string one = (dir.path / "one.png").string(),
                    sheet = (dir.path / "sheet.png").string();
  auto r = test::run_cordgrasp("render --regions " + regions + " --region 2 --size 160x120 --out " +
                               quoted(one));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(png_size(one), std::make_pair(160u, 120u));
  r = test::run_cordgrasp("render --regions " + regions +
                          " --sheet 5 --size 100x80 --no-caption --out " + quoted(sheet));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(png_size(sheet), std::make_pair(12u + 2u * 112u, 12u + 92u));  // 2 tiles, 1 row
  r = test::run_cordgrasp("render --regions " + regions + " --region 3 --out " + quoted(one));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("has regions 1..2"), std::string::npos) << r.output;
}

TEST(CliRender, BadRegionsFileIsNamed) {
  TempDir dir;
  const std::string bad = (dir.path / "bad.json").string();
  std::ofstream(bad) << "{\"regions\": [{\"p1\": [0, 0, 0]}]}";
  const auto r = test::run_cordgrasp("render --regions " + quoted(bad) + " --out " +
                                     quoted((dir.path / "x.png").string()));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find(bad), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("missing field"), std::string::npos) << r.output;
}

TEST(CliRender, PlanGraspsMayCarryTheirRegion) {
  TempDir dir;
  const std::string plan = (dir.path / "plan.json").string();
  const std::string out = (dir.path / "g.png").string();
  auto r = test::run_cordgrasp("plan --object " +
                               quoted(test::source_dir() + "/assets/objects/box.obj") +
                               " --grasps 1 --out " + quoted(plan));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  nlohmann::json j;
  std::ifstream(plan) >> j;
  j["grasps"][0]["region"] = {{"p1", {0.2, 0, 0.04}},
                              {"p2", {0, 0.1, 0.04}},
                              {"p3", {0, -0.1, 0.04}},
                              {"normal", {0, 0, 1}},
                              {"p_l", {0, 0.025, 0.04}},
                              {"p_r", {0, -0.025, 0.04}},
                              {"p_m", {0, 0, 0.04}},
                              {"case", "I"},
                              {"n", 0},
                              {"front_cords", {{{0.025, -0.025, 0.04}, {0.025, 0.025, 0.04}}}},
                              {"xi_m", 0.03},
                              {"chi_m2", 1e-5}};
  std::ofstream(plan) << j.dump();
  r = test::run_cordgrasp("render --plan " + quoted(plan) + " --size 80x60 --out " + quoted(out));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(png_size(out), std::make_pair(80u, 60u));
  j["grasps"][0]["region"].erase("front_cords");
  std::ofstream(plan) << j.dump();
  r = test::run_cordgrasp("render --plan " + quoted(plan) + " --size 80x60 --out " + quoted(out));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("grasps[0].region: region: missing field 'front_cords'"),
            std::string::npos)
      << r.output;
}

TEST(CliRender, BadSizeIsOneLineErrorNamingIt) {
  TempDir dir;
  const auto r = test::run_cordgrasp("render --object " + quoted(kMug) + " --size 320by200 --out " +
                                     quoted((dir.path / "x.png").string()));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(r.output.rfind("cordgrasp: error: --size '320by200'", 0), 0u) << r.output;
  EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << r.output;
  EXPECT_FALSE(fs::exists(dir.path / "x.png"));
}

TEST(CliRender, ApproachViewNeedsADirectionForAnObject) {
  TempDir dir;
  const std::string out = (dir.path / "x.png").string();
  auto r = test::run_cordgrasp("render --object " + quoted(kMug) + " --view approach --out " +
                               quoted(out));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("--approach"), std::string::npos) << r.output;
  r = test::run_cordgrasp("render --object " + quoted(kMug) +
                          " --view approach --approach 0,0,-1 --size 64x48 --out " + quoted(out));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(png_size(out), std::make_pair(64u, 48u));
}

TEST(CliRender, MissingObjectFileIsNamed) {
  TempDir dir;
  const std::string missing = (dir.path / "nope.obj").string();
  const auto r = test::run_cordgrasp("render --object " + quoted(missing) + " --out " +
                                     quoted((dir.path / "x.png").string()));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find(missing), std::string::npos) << r.output;
}

TEST(CliRender, UnwritableOutputIsNamed) {
  TempDir dir;
  const std::string out = (dir.path / "no" / "dir" / "x.png").string();
  const auto r =
      test::run_cordgrasp("render --object " + quoted(kMug) + " --size 32x32 --out " + quoted(out));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find(out), std::string::npos) << r.output;
}

TEST(CliRender, OsMesaIsLoadedOnlyByACommandThatRenders) {
  // The dynamic loader lists every library it opens under LD_DEBUG=files.
  const test::ScopedEnv debug("LD_DEBUG", std::string("files"));
  const auto info = test::run_cordgrasp("info --object " + quoted(kMug));
  ASSERT_EQ(info.exit_code, 0) << info.output;
  EXPECT_NE(info.output.find("libc.so"), std::string::npos) << "LD_DEBUG had no effect";
  EXPECT_EQ(info.output.find("libOSMesa"), std::string::npos) << info.output;
  TempDir dir;
  const auto render =
      test::run_cordgrasp("render --object " + quoted(kMug) + " --size 32x32 --out " +
                          quoted((dir.path / "x.png").string()));
  ASSERT_EQ(render.exit_code, 0) << render.output;
  EXPECT_NE(render.output.find("libOSMesa"), std::string::npos);
}

}  // namespace
}  // namespace cordgrasp
