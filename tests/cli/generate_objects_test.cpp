#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "test_files.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

namespace fs = std::filesystem;

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

using test::TempDir;

TEST(CliGenerateObjects, RegeneratesTheShippedObjectsByteForByte) {
  TempDir dir;
  const test::CommandResult r =
      test::run_cordgrasp("generate-objects --out-dir \"" + dir.path.string() + "\"");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const fs::path shipped = fs::path(test::source_dir()) / "assets/objects";
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir.path)) {
    ++files;
    const fs::path committed = shipped / e.path().filename();
    ASSERT_TRUE(fs::exists(committed)) << committed;
    EXPECT_TRUE(read_bytes(e.path()) == read_bytes(committed))
        << e.path().filename() << " differs from the committed asset: regenerate assets/objects";
  }
  EXPECT_EQ(files, 10);
  EXPECT_EQ(int(test::files_in(shipped.string(), ".obj").size()), files);
}

TEST(CliGenerateObjects, OnlyWritesTheNamedObjectsAndRejectsUnknownNames) {
  TempDir dir;
  const std::string out = "--out-dir \"" + dir.path.string() + "\"";
  const test::CommandResult r = test::run_cordgrasp("generate-objects --only mug torus " + out);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(test::files_in(dir.path.string(), ".obj"),
            (std::vector<std::string>{(dir.path / "mug.obj").string(),
                                      (dir.path / "torus.obj").string()}));
  EXPECT_NE(test::run_cordgrasp("generate-objects --only teapot " + out).exit_code, 0);
  EXPECT_NE(test::run_cordgrasp("generate-objects").exit_code, 0);  // --out-dir is required
}

}  // namespace
}  // namespace cordgrasp
