// PNG writing (atomic, libpng) and reading.
#include "cordgrasp/render/png_io.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cordgrasp/core/error.h"

namespace cordgrasp {
namespace {

namespace fs = std::filesystem;

// A fresh, empty directory under the system temp dir, removed at scope exit.
struct TempDir {
  fs::path path;
  TempDir() {
    path = fs::temp_directory_path() /
           ("cordgrasp_png_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
};

Image gradient_image(int w, int h) {
  Image image = make_image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      p[0] = static_cast<std::uint8_t>(x * 7);
      p[1] = static_cast<std::uint8_t>(y * 13);
      p[2] = static_cast<std::uint8_t>((x + y) * 3);
      p[3] = static_cast<std::uint8_t>(255 - x);
    }
  return image;
}

TEST(WritePng, RgbReadsBackWithSameSizeAndColoursAndOpaqueAlpha) {
  TempDir dir;
  const Image image = gradient_image(37, 21);
  const std::string path = (dir.path / "g.png").string();
  write_png(path, image);
  const Image back = read_png(path);
  ASSERT_EQ(back.width, 37);
  ASSERT_EQ(back.height, 21);
  for (int y = 0; y < 21; ++y)
    for (int x = 0; x < 37; ++x) {
      for (int c = 0; c < 3; ++c) ASSERT_EQ(back.pixel(x, y)[c], image.pixel(x, y)[c]);
      ASSERT_EQ(back.pixel(x, y)[3], 255);
    }
}

TEST(WritePng, RgbaKeepsAlphaExactly) {
  TempDir dir;
  const Image image = gradient_image(16, 9);
  const std::string path = (dir.path / "a.png").string();
  write_png(path, image, /*keep_alpha=*/true);
  const Image back = read_png(path);
  EXPECT_EQ(back.rgba, image.rgba);
}

TEST(WritePng, LeavesNoTemporaryFileBehind) {
  TempDir dir;
  write_png((dir.path / "x.png").string(), gradient_image(4, 4));
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir.path)) {
    EXPECT_EQ(e.path().filename(), "x.png");
    ++files;
  }
  EXPECT_EQ(files, 1);
}

TEST(WritePng, ThrowsNamingPathWhenDirectoryMissing) {
  TempDir dir;
  const std::string path = (dir.path / "no" / "such" / "dir.png").string();
  try {
    write_png(path, gradient_image(4, 4));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

TEST(EncodePng, RejectsEmptyImage) { EXPECT_THROW(encode_png(Image{}), std::runtime_error); }

TEST(ReadPng, ThrowsNamingPathWhenFileMissingOrNotPng) {
  TempDir dir;
  const std::string missing = (dir.path / "missing.png").string();
  try {
    read_png(missing);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }
  const std::string text = (dir.path / "text.png").string();
  { std::ofstream(text) << "not a png"; }
  EXPECT_THROW(read_png(text), InputError);
}

}  // namespace
}  // namespace cordgrasp
