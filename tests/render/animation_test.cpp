// Animated WebP: frames and their display times survive an encode and decode; bad input is
// refused with a message.
#include <gtest/gtest.h>

#include <cstdlib>
#include <stdexcept>

#include "cordgrasp/core/error.h"
#include "cordgrasp/render/animation.h"

namespace cordgrasp {
namespace {

constexpr int kColourTolerance = 12;  ///< lossy WebP: per-channel error on a flat colour

Image flat(int w, int h, double r, double g, double b) {
  return make_image(w, h, Eigen::Vector4d(r, g, b, 1.0));
}

bool near_colour(const Image& image, int x, int y, int r, int g, int b) {
  const std::uint8_t* p = image.pixel(x, y);
  return std::abs(p[0] - r) <= kColourTolerance && std::abs(p[1] - g) <= kColourTolerance &&
         std::abs(p[2] - b) <= kColourTolerance;
}

TEST(Animation, FramesAndTheirDurationsSurviveEncodingAndDecoding) {
  AnimationParams params;
  params.frame_rate_hz = 20.0;
  AnimationEncoder encoder(64, 48, params);
  encoder.add_frame(flat(64, 48, 1, 0, 0));       // 50 ms (the frame rate)
  Image blue_square = flat(64, 48, 1, 1, 1);
  fill_rect(blue_square, 16, 12, 32, 24, Eigen::Vector4d(0, 0, 1, 1));
  encoder.add_frame(blue_square, 0.2);            // 200 ms
  encoder.add_frame(flat(64, 48, 0, 1, 0), 1.0);  // 1 s
  EXPECT_EQ(encoder.frame_count(), 3);
  const std::string bytes = encoder.finish();
  ASSERT_GT(bytes.size(), 12u);
  EXPECT_EQ(bytes.substr(0, 4), "RIFF");
  EXPECT_EQ(bytes.substr(8, 4), "WEBP");

  const std::vector<AnimationFrame> frames = decode_animation(bytes);
  ASSERT_EQ(frames.size(), 3u);
  EXPECT_EQ(frames[0].image.width, 64);
  EXPECT_EQ(frames[0].image.height, 48);
  EXPECT_NEAR(frames[0].timestamp_s, 0.05, 1e-3);
  EXPECT_NEAR(frames[1].timestamp_s, 0.25, 1e-3);
  EXPECT_NEAR(frames[2].timestamp_s, 1.25, 1e-3);
  EXPECT_TRUE(near_colour(frames[0].image, 5, 5, 255, 0, 0));
  EXPECT_TRUE(near_colour(frames[1].image, 32, 24, 0, 0, 255));
  EXPECT_TRUE(near_colour(frames[1].image, 3, 3, 255, 255, 255));
  EXPECT_TRUE(near_colour(frames[2].image, 60, 40, 0, 255, 0));
}

TEST(Animation, WrongFrameSizeBadSettingsAndNoFramesAreRefused) {
  EXPECT_THROW(AnimationEncoder(0, 10), std::invalid_argument);
  AnimationParams bad;
  bad.quality = 101;
  EXPECT_THROW(AnimationEncoder(10, 10, bad), std::invalid_argument);
  AnimationEncoder encoder(10, 10);
  EXPECT_THROW(encoder.add_frame(flat(12, 10, 0, 0, 0)), std::invalid_argument);
  EXPECT_THROW(encoder.finish(), std::runtime_error);  // no frames
}

TEST(Animation, BytesThatAreNotWebpAreAnInputErrorNamingTheFile) {
  try {
    decode_animation("RIFF\x10\0\0\0WEBPjunk", "animation 'x.webp'");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("x.webp"), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_animation("/nonexistent/a.webp"), InputError);
}

}  // namespace
}  // namespace cordgrasp
