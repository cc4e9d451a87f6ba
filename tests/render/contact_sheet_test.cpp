// Contact sheets and caption text.
#include "cordgrasp/render/contact_sheet.h"

#include <gtest/gtest.h>

#include "cordgrasp/render/text.h"
#include "image_stats.h"

namespace cordgrasp {
namespace {

/// The font is a declared dependency (tools/install-deps.sh): its absence is a failure.
const char* const kFontMissing =
    "caption font absent: install fonts-dejavu-core (tools/install-deps.sh)";

TEST(ContactSheet, LaysOutTilesRowMajorOnAGrid) {
  std::vector<Image> tiles;
  for (int i = 0; i < 5; ++i) tiles.push_back(make_image(40, 30, Rgba(0.1 * i, 0.5, 0.2, 1.0)));
  ContactSheetParams params;
  params.spacing_px = 6;
  const Image sheet = compose_contact_sheet(tiles, {}, params);
  // ceil(sqrt(5)) = 3 columns, 2 rows, no caption band.
  EXPECT_EQ(sheet.width, 6 + 3 * (40 + 6));
  EXPECT_EQ(sheet.height, 6 + 2 * (30 + 6));
  for (int i = 0; i < 5; ++i) {
    const int cx = 6 + (i % 3) * 46 + 20, cy = 6 + (i / 3) * 36 + 15;
    EXPECT_EQ(sheet.pixel(cx, cy)[0], to_byte(0.1 * i)) << i;
  }
  EXPECT_EQ(sheet.pixel(6 + 2 * 46 + 20, 6 + 36 + 15)[0], 255);  // sixth cell is empty
}

TEST(ContactSheet, HonoursColumnsAndCentresSmallerTiles) {
  std::vector<Image> tiles = {make_image(40, 30, Rgba(0, 0, 0, 1)),
                              make_image(20, 10, Rgba(0, 0, 0, 1))};
  ContactSheetParams params;
  params.columns = 1;
  params.spacing_px = 0;
  const Image sheet = compose_contact_sheet(tiles, {}, params);
  EXPECT_EQ(sheet.width, 40);
  EXPECT_EQ(sheet.height, 60);
  const auto second = test::select_pixels(sheet, [](int r, int, int) { return r == 0; });
  EXPECT_EQ(second.count, 40 * 30 + 20 * 10);
  EXPECT_EQ(sheet.pixel(10, 30 + 10)[0], 0);  // (10..29, 40..49) is the second tile
  EXPECT_EQ(sheet.pixel(5, 30 + 10)[0], 255);
}

TEST(ContactSheet, CaptionsGoUnderTheirTiles) {
  ASSERT_TRUE(caption_font_available()) << kFontMissing;
  std::vector<Image> tiles(2, make_image(120, 60, Rgba(1, 1, 1, 1)));
  ContactSheetParams params;
  params.spacing_px = 4;
  params.caption_size_px = 14;
  const Image sheet = compose_contact_sheet(tiles, {"first", ""}, params);
  const int band = static_cast<int>(std::lround(1.7 * 14));
  EXPECT_EQ(sheet.height, 4 + 60 + band + 4);
  const auto ink = test::non_white(sheet, 200);
  ASSERT_GT(ink.count, 20);
  EXPECT_GE(ink.y_min, 4 + 60);   // below the tiles
  EXPECT_LT(ink.x_max, 4 + 120);  // under the first tile only
}

TEST(ContactSheet, ThrowsWithoutTiles) {
  EXPECT_THROW(compose_contact_sheet({}), std::invalid_argument);
}

TEST(Text, WiderTextMeasuresWiderAndLargerFontWider) {
  ASSERT_TRUE(caption_font_available()) << kFontMissing;
  EXPECT_GT(measure_text("grasp", 16), 0);
  EXPECT_GT(measure_text("grasp planner", 16), measure_text("grasp", 16));
  EXPECT_GT(measure_text("grasp", 32), measure_text("grasp", 16));
}

TEST(Text, DrawsGreekLettersAsInk) {
  ASSERT_TRUE(caption_font_available()) << kFontMissing;
  Image a = make_image(60, 30);
  ASSERT_TRUE(draw_text(a, "αε", 5, 22, 20));
  EXPECT_GT(test::non_white(a, 128).count, 20);
}

TEST(Text, CenteredTextShrinksOrElidesToFit) {
  ASSERT_TRUE(caption_font_available()) << kFontMissing;
  Image image = make_image(80, 20);
  const std::string long_text(200, 'M');
  ASSERT_TRUE(draw_text_centered(image, long_text, 0, 0, 80, 20, 16, 4));
  const auto ink = test::non_white(image, 250);
  ASSERT_GT(ink.count, 0);
  EXPECT_GE(ink.x_min, 3);
  EXPECT_LE(ink.x_max, 80 - 4);
}

}  // namespace
}  // namespace cordgrasp
