// --package-path NAME=DIR: a URDF with package:// meshes loads with it; without it the error
// names the package.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cordgrasp/core/draft_hand_description.h"
#include "test_files.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

const std::string kPackage = "cordgrasp_test_meshes";

std::string hand() { return test::test_data("hands/package_uri/package_uri.yaml"); }
std::string package_dir() { return test::test_data("hands/package_uri/ros/" + kPackage); }

TEST(PackagePathCli, LoadsAPackageUriHandWithThePackagePath) {
  const test::CommandResult r = test::run_cordgrasp(
      "info --hand " + hand() + " --package-path " + kPackage + "=" + package_dir());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("package_uri"), std::string::npos) << r.output;
}

TEST(PackagePathCli, WithoutThePackagePathTheErrorNamesThePackage) {
  const test::CommandResult r =
      test::run_cordgrasp("info --hand " + hand());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("ROS package '" + kPackage + "' not found"), std::string::npos)
      << r.output;
}

TEST(PackagePathCli, HandInitResolvesPackageUrisThroughIt) {
  const std::string urdf = test::test_data("hands/package_uri/package_uri.urdf");
  const std::string out = ::testing::TempDir() + "/package_uri_draft.yaml";
  const test::CommandResult without =
      test::run_cordgrasp("hand init --urdf " + urdf + " --out " + out);
  EXPECT_NE(without.exit_code, 0);
  EXPECT_NE(without.output.find("ROS package '" + kPackage + "' not found"), std::string::npos)
      << without.output;
  // With it the meshes load; this one-link fixture then has no finger to draft.
  const test::CommandResult with = test::run_cordgrasp(
      "hand init --urdf " + urdf + " --out " + out + " --package-path " + kPackage + "=" +
      package_dir());
  EXPECT_EQ(with.output.find("not found"), std::string::npos) << with.output;
  EXPECT_NE(with.output.find("no joint closes any finger"), std::string::npos) << with.output;
}

// A description's package_paths (DIR relative to the file) serve every command, plan, validate
// and run included, without the option; hand init --package-path writes them.
TEST(PackagePathCli, ADescriptionRecordsItsPackagePaths) {
  const test::TempDir dir;
  const std::string relative =
      std::filesystem::relative(package_dir(), dir.path).lexically_normal().string();
  const std::string desc = dir.write(
      "with_packages.yaml",
      "format: 1\nurdf: " + test::test_data("hands/package_uri/package_uri.urdf") +
          "\ngcp: {link: palm, xyz: [0.02, 0, 0.12]}\n"
          "actors: [{name: finger, joints: {knuckle: 1}}]\n"
          "package_paths: {" + kPackage + ": " + relative + "}\n");
  const test::CommandResult r = test::run_cordgrasp("info --hand " + desc);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string bad = dir.write(
      "bad_dir.yaml",
      "format: 1\nurdf: " + test::test_data("hands/package_uri/package_uri.urdf") +
          "\ngcp: {link: palm, xyz: [0.02, 0, 0.12]}\n"
          "actors: [{name: finger, joints: {knuckle: 1}}]\n"
          "package_paths: {" + kPackage + ": no/such/dir}\n");
  const test::CommandResult refused = test::run_cordgrasp("info --hand " + bad);
  EXPECT_NE(refused.exit_code, 0);
  EXPECT_NE(refused.output.find("package_paths." + kPackage), std::string::npos)
      << refused.output;
  EXPECT_NE(refused.output.find("is not a directory"), std::string::npos) << refused.output;

  // A draft made with package directories records them.
  HandLoadOptions options;
  options.package_paths[kPackage] = package_dir();
  const HandDraft draft = draft_hand_description(
      test::source_dir() + "/assets/hands/parallel_gripper/parallel_gripper.urdf",
      dir.file("draft.yaml"), options);
  EXPECT_NE(draft.yaml.find("package_paths:\n  \"" + kPackage + "\": "), std::string::npos)
      << draft.yaml;
}

TEST(PackagePathCli, AnotherPackageDoesNotHelp) {
  const test::CommandResult r = test::run_cordgrasp("info --hand " + hand() +
                                                    " --package-path other=" + package_dir());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("'" + kPackage + "'"), std::string::npos) << r.output;
}

TEST(PackagePathCli, RefusesAMissingDirectoryAndAMalformedItem) {
  const test::CommandResult missing = test::run_cordgrasp(
      "info --hand " + hand() + " --package-path " + kPackage + "=/no/such/dir");
  EXPECT_NE(missing.exit_code, 0);
  EXPECT_NE(missing.output.find("is not a directory"), std::string::npos) << missing.output;
  const test::CommandResult malformed =
      test::run_cordgrasp("info --hand " + hand() + " --package-path " + kPackage);
  EXPECT_NE(malformed.exit_code, 0);
  EXPECT_NE(malformed.output.find("is not NAME=DIR"), std::string::npos) << malformed.output;
}

// plan, validate and run find packages through ROS_PACKAGE_PATH and AMENT_PREFIX_PATH only
// (their command lines stay short); the other commands loading a hand take the option.
TEST(PackagePathCli, EveryCommandLoadingAHandTakesIt) {
  for (const std::string cmd : {"render", "explore", "info", "bench", "export", "hand init"}) {
    const test::CommandResult r = test::run_cordgrasp(cmd + " --help");
    EXPECT_NE(r.output.find("--package-path"), std::string::npos) << cmd;
  }
}

}  // namespace
}  // namespace cordgrasp
