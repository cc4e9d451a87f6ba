// `cordgrasp plan` then `cordgrasp render --plan`: the picture of a real plan.
#include <gtest/gtest.h>

#include <filesystem>

#include "cordgrasp/core/hand_fingers.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/render/png_io.h"
#include "cordgrasp/jobs/hand_scene.h"
#include "image_stats.h"
#include "test_files.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

namespace fs = std::filesystem;

using test::pixels_of_hue;
using test::quoted;

TEST(RenderPlan, DefaultHandOnMugShowsHandAndObjectColours) {
  const fs::path dir = fs::temp_directory_path() / "cordgrasp_render_plan_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string plan = (dir / "plan.json").string(), png = (dir / "grasp.png").string();
  auto r = test::run_cordgrasp("plan --object " +
                               quoted(test::source_dir() + "/assets/objects/mug.obj") +
                               " --grasps 1 --out " + quoted(plan));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = test::run_cordgrasp("render --plan " + quoted(plan) + " --size 480x360 --out " + quoted(png));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("warning"), std::string::npos) << r.output;  // cords replayed
  const Image image = read_png(png);
  test::save_for_inspection(image, "plan_default_hand_mug");
  ASSERT_EQ(image.width, 480);
  ASSERT_EQ(image.height, 360);

  const HandModel hand = load_hand(default_hand_name());
  const auto colors = hand_link_colors(hand);
  int finger_px = 0;
  for (const Finger& f : hand_fingers(hand)) finger_px += pixels_of_hue(image, colors[f.links[0]]);
  EXPECT_GT(finger_px, 500);
  EXPECT_GT(pixels_of_hue(image, colors[hand.root_link]), 500);  // the palm's slate
  const int object_px = test::select_pixels(image, [](int r, int g, int b) {
                          return std::abs(r - g) <= 2 && std::abs(g - b) <= 2 && r > 60 && r < 240;
                        }).count;
  EXPECT_GT(object_px, 2000);
  fs::remove_all(dir);
}

TEST(RenderPlan, SheetOfGraspsAndGraspOutOfRange) {
  const fs::path dir = fs::temp_directory_path() / "cordgrasp_render_plan_sheet_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string plan = (dir / "plan.json").string(), png = (dir / "sheet.png").string();
  auto r = test::run_cordgrasp("plan --object " +
                               quoted(test::source_dir() + "/assets/objects/box.obj") +
                               " --grasps 2 --out " + quoted(plan));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = test::run_cordgrasp("render --plan " + quoted(plan) +
                          " --sheet 2 --size 120x90 --no-caption --cones --out " + quoted(png));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Image sheet = read_png(png);
  EXPECT_EQ(sheet.width, 12 + 2 * (120 + 12));  // two tiles in a row, no caption bands
  EXPECT_EQ(sheet.height, 12 + 90 + 12);
  r = test::run_cordgrasp("render --plan " + quoted(plan) + " --grasp 7 --out " + quoted(png));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("has grasps 0..1"), std::string::npos) << r.output;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cordgrasp
