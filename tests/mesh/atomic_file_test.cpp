// write_file_atomically: the whole file or nothing, a readable reason when it cannot.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cordgrasp/core/atomic_file.h"
#include "cordgrasp/core/error.h"
#include "test_files.h"

namespace cordgrasp {
namespace {

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(WriteFileAtomically, WritesTheBytesAndLeavesNoTemporaryFile) {
  const test::TempDir dir;
  write_file_atomically(dir.file("a.txt"), "hello\n");
  EXPECT_EQ(read_all(dir.file("a.txt")), "hello\n");
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir.path)) files += !e.is_directory();
  EXPECT_EQ(files, 1);
}

TEST(WriteFileAtomically, ADirectoryInTheWayIsNamedWithTheReason) {
  const test::TempDir dir;
  std::filesystem::create_directories(dir.path / "out.json");
  try {
    write_file_atomically(dir.file("out.json"), "{}");
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("out.json"), std::string::npos) << what;
    EXPECT_NE(what.find("is a directory"), std::string::npos) << what;
    EXPECT_EQ(what.find("Success"), std::string::npos) << what;
  }
}

TEST(WriteFileAtomically, ConcurrentWritersOfOneFileEachLeaveAWholeFile) {
  const test::TempDir dir;
  const std::string path = dir.file("shared.txt");
  const std::string a(200000, 'a'), b(200000, 'b');
  std::vector<std::thread> writers;
  for (int t = 0; t < 4; ++t)
    writers.emplace_back([&, t] {
      for (int i = 0; i < 20; ++i) write_file_atomically(path, t % 2 ? a : b);
    });
  for (auto& w : writers) w.join();
  const std::string text = read_all(path);
  EXPECT_TRUE(text == a || text == b) << "mixed file of " << text.size() << " bytes";
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir.path)) files += !e.is_directory();
  EXPECT_EQ(files, 1) << "temporary files left behind";
}

}  // namespace
}  // namespace cordgrasp
