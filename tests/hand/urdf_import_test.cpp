// URDF import through load_hand: trees walked without recursion (cycles and second parents are
// errors, deep chains load), and package:// mesh URIs resolved through HandLoadOptions,
// ROS_PACKAGE_PATH and AMENT_PREFIX_PATH.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "cordgrasp/core/error.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/kinematics.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

namespace fs = std::filesystem;
using test::test_data;

constexpr const char* kPackage = "cordgrasp_test_meshes";

/// Sets (or unsets, for nullopt) an environment variable for the scope; restores it after.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::optional<std::string>& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value)
      ::setenv(name, value->c_str(), 1);
    else
      ::unsetenv(name);
  }
  ~ScopedEnv() {
    if (old_)
      ::setenv(name_, old_->c_str(), 1);
    else
      ::unsetenv(name_);
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

/// A fresh directory under the system temp dir, removed at the end of the scope.
class TempDir {
 public:
  explicit TempDir(const std::string& tag)
      : path_(fs::temp_directory_path() /
              ("cordgrasp_" + tag + "_" + std::to_string(::getpid()))) {
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() { fs::remove_all(path_); }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

std::string package_hand() { return test_data("hands/package_uri/package_uri.yaml"); }
fs::path package_dir() { return fs::path(test_data("hands/package_uri/ros")) / kPackage; }

std::string load_error(const std::string& path, const HandLoadOptions& options = {}) {
  try {
    load_hand(path, options);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

/// Both mesh geometries of the palm come from `dir`/meshes/tetra.obj.
void expect_meshes_from(const HandModel& hand, const fs::path& dir) {
  const std::string expected = (dir / "meshes" / "tetra.obj").lexically_normal().string();
  const Link& palm = hand.links.at(find_link(hand, "palm"));
  ASSERT_EQ(palm.collisions.size(), 1u);
  ASSERT_EQ(palm.visuals.size(), 1u);
  EXPECT_EQ(palm.collisions[0].mesh_path, expected);
  EXPECT_EQ(palm.visuals[0].mesh_path, expected);
  ASSERT_TRUE(palm.collisions[0].mesh);
  EXPECT_EQ(palm.collisions[0].mesh->vertices.size(), 4u);
}

// --- tree walk ---------------------------------------------------------------------------------

TEST(UrdfImport, JointCycleIsAnErrorNamingTheUrdfAndTheJointsOfTheLoop) {
  const std::string what = load_error(test_data("hands/bad/joint_cycle.yaml"));
  EXPECT_NE(what.find("joint_cycle.urdf'"), std::string::npos) << what;
  EXPECT_NE(what.find("joints form a cycle through link 'a': 'a_b' -> 'b_a'"), std::string::npos)
      << what;
}

TEST(UrdfImport, LinkWithTwoParentJointsIsAnErrorNamingBothJoints) {
  const std::string what = load_error(test_data("hands/bad/two_parents.yaml"));
  EXPECT_NE(what.find("two_parents.urdf'"), std::string::npos) << what;
  // The joint met first in the depth-first walk (urdfdom lists child joints by name) comes first.
  EXPECT_NE(what.find("link 'c' is the child of two joints, 'b_c' and 'palm_c'"),
            std::string::npos)
      << what;
}

TEST(UrdfImport, DeepChainLoadsInDepthFirstOrder) {
  // Deep enough that the former recursive walk (one std::function frame per link) would need a
  // large share of a default 8 MB stack; the loop needs none.
  constexpr int kLinks = 20000;
  TempDir dir("deep_chain");
  {
    std::ofstream urdf(dir.path() / "chain.urdf");
    urdf << "<?xml version=\"1.0\"?>\n<robot name=\"chain\">\n";
    for (int i = 0; i < kLinks; ++i)
      urdf << "<link name=\"l" << i << "\"><inertial><mass value=\"0.001\"/><inertia ixx=\"1e-8\""
           << " ixy=\"0\" ixz=\"0\" iyy=\"1e-8\" iyz=\"0\" izz=\"1e-8\"/></inertial></link>\n";
    for (int i = 1; i < kLinks; ++i)
      urdf << "<joint name=\"j" << i << "\" type=\"" << (i == 1 ? "revolute" : "fixed")
           << "\"><parent link=\"l" << i - 1 << "\"/><child link=\"l" << i << "\"/>"
           << "<origin xyz=\"0 0 0.00001\"/><axis xyz=\"0 1 0\"/>"
           << "<limit lower=\"0\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint>\n";
    urdf << "</robot>\n";
    std::ofstream yaml(dir.path() / "chain.yaml");
    yaml << "format: 1\nurdf: chain.urdf\ngcp: {link: l0}\n"
         << "actors: [{name: finger, joints: {j1: 1}}]\n";
  }
  const HandModel h = load_hand((dir.path() / "chain.yaml").string());
  ASSERT_EQ(h.links.size(), static_cast<size_t>(kLinks));
  ASSERT_EQ(h.joints.size(), static_cast<size_t>(kLinks - 1));
  for (int j = 0; j < kLinks - 1; ++j) {
    EXPECT_EQ(h.joints[j].parent_link, j);
    EXPECT_EQ(h.joints[j].child_link, j + 1);
  }
  EXPECT_EQ(h.links.back().name, "l" + std::to_string(kLinks - 1));
}

// --- package:// URIs ---------------------------------------------------------------------------

TEST(UrdfImportPackageUri, ResolvedThroughTheOptionsMap) {
  ScopedEnv ros("ROS_PACKAGE_PATH", std::nullopt);
  ScopedEnv ament("AMENT_PREFIX_PATH", std::nullopt);
  HandLoadOptions options;
  options.package_paths[kPackage] = package_dir().string();
  expect_meshes_from(load_hand(package_hand(), options), package_dir());
}

TEST(UrdfImportPackageUri, ResolvedThroughRosPackagePathParentHoldingPackageXml) {
  ScopedEnv ros("ROS_PACKAGE_PATH", "/nonexistent/ros:" + package_dir().parent_path().string());
  ScopedEnv ament("AMENT_PREFIX_PATH", std::nullopt);
  expect_meshes_from(load_hand(package_hand()), package_dir());
}

TEST(UrdfImportPackageUri, ResolvedThroughRosPackagePathListingThePackageItself) {
  ScopedEnv ros("ROS_PACKAGE_PATH", package_dir().string() + "/");
  ScopedEnv ament("AMENT_PREFIX_PATH", std::nullopt);
  expect_meshes_from(load_hand(package_hand()), package_dir());
}

TEST(UrdfImportPackageUri, ResolvedThroughAmentPrefixPathShare) {
  TempDir prefix("ament_prefix");
  const fs::path share = prefix.path() / "share" / kPackage;
  fs::create_directories(share / "meshes");
  fs::copy_file(package_dir() / "meshes" / "tetra.obj", share / "meshes" / "tetra.obj");
  ScopedEnv ros("ROS_PACKAGE_PATH", std::nullopt);
  ScopedEnv ament("AMENT_PREFIX_PATH", "/nonexistent/prefix:" + prefix.path().string());
  expect_meshes_from(load_hand(package_hand()), share);
}

TEST(UrdfImportPackageUri, OptionsMapComesBeforeTheEnvironment) {
  TempDir other("package_copy");
  fs::create_directories(other.path() / "meshes");
  fs::copy_file(package_dir() / "meshes" / "tetra.obj", other.path() / "meshes" / "tetra.obj");
  ScopedEnv ros("ROS_PACKAGE_PATH", package_dir().parent_path().string());
  ScopedEnv ament("AMENT_PREFIX_PATH", std::nullopt);
  HandLoadOptions options;
  options.package_paths[kPackage] = other.path().string();
  expect_meshes_from(load_hand(package_hand(), options), other.path());
}

TEST(UrdfImportPackageUri, UnknownPackageIsAnErrorNamingTheUrdfAndThePackage) {
  ScopedEnv ros("ROS_PACKAGE_PATH", "/nonexistent/ros");
  ScopedEnv ament("AMENT_PREFIX_PATH", std::nullopt);
  HandLoadOptions options;
  options.package_paths["some_other_package"] = package_dir().string();
  const std::string what = load_error(package_hand(), options);
  EXPECT_EQ(what.rfind("load_hand: '", 0), 0u) << what;
  EXPECT_NE(what.find("package_uri.urdf'"), std::string::npos) << what;
  EXPECT_NE(what.find("ROS package 'cordgrasp_test_meshes' not found"), std::string::npos)
      << what;
}

TEST(UrdfImportPackageUri, RosPackagePathDirectoryWithoutPackageXmlIsNotAPackage) {
  TempDir root("ros_root");
  fs::create_directories(root.path() / kPackage / "meshes");  // no package.xml
  fs::copy_file(package_dir() / "meshes" / "tetra.obj",
                root.path() / kPackage / "meshes" / "tetra.obj");
  ScopedEnv ros("ROS_PACKAGE_PATH", root.path().string());
  ScopedEnv ament("AMENT_PREFIX_PATH", std::nullopt);
  EXPECT_NE(load_error(package_hand()).find("ROS package 'cordgrasp_test_meshes' not found"),
            std::string::npos);
}

}  // namespace
}  // namespace cordgrasp
