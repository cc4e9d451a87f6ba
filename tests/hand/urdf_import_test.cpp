// URDF import through load_hand: trees walked without recursion (cycles and second parents are
// errors, deep chains load), and package:// mesh URIs resolved through HandLoadOptions,
// ROS_PACKAGE_PATH and AMENT_PREFIX_PATH.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>

#include "cordgrasp/core/error.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/kinematics.h"
#include "scoped_env.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

namespace fs = std::filesystem;
using test::test_data;

constexpr const char* kPackage = "cordgrasp_test_meshes";

using test::ScopedEnv;

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
  const fs::path index = prefix.path() / "share" / "ament_index" / "resource_index" / "packages";
  fs::create_directories(index);
  std::ofstream(index / kPackage).flush();  // ament's marker of an installed package: empty
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

// --- package:// through a crawl of ROS_PACKAGE_PATH (rospack, catkin) ---------------------------

/// A package folder as catkin has it: `dir`/package.xml naming `name` (with comments, one of
/// them holding a <name> element, as generated package.xml files have) and meshes/tetra.obj.
void write_package(const fs::path& dir, const std::string& name) {
  fs::create_directories(dir / "meshes");
  fs::copy_file(package_dir() / "meshes" / "tetra.obj", dir / "meshes" / "tetra.obj");
  std::ofstream(dir / "package.xml")
      << "<?xml version=\"1.0\"?>\n<package format=\"3\">\n"
      << "  <!-- <name>not_this_name</name> -->\n  <name>\n    " << name << "\n  </name>\n"
      << "  <version>0.1.0</version>\n  <!-- one line description -->\n"
      << "  <description>meshes</description>\n"
      << "  <maintainer email=\"a@example.com\">a</maintainer>\n  <license>MIT</license>\n"
      << "  <buildtool_depend>catkin</buildtool_depend>\n</package>\n";
}

/// The package_uri hand with its URDF's package://cordgrasp_test_meshes/... renamed to
/// package://`package`/..., written to `dir`; returns the description's path.
std::string write_hand_naming(const fs::path& dir, const std::string& package) {
  fs::create_directories(dir);
  std::ifstream in(test_data("hands/package_uri/package_uri.urdf"));
  std::string urdf((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string from = std::string("package://") + kPackage + "/";
  for (size_t at = urdf.find(from); at != std::string::npos; at = urdf.find(from, at))
    urdf.replace(at, from.size(), "package://" + package + "/");
  std::ofstream(dir / "package_uri.urdf") << urdf;
  fs::copy_file(package_hand(), dir / "package_uri.yaml");
  return (dir / "package_uri.yaml").string();
}

// Each test crawls its own temp dir: the crawl is cached per ROS_PACKAGE_PATH value.

TEST(UrdfImportRosPackageCrawl, FindsAPackageInARepositoryFolderOfACatkinWorkspaceByItsName) {
  TempDir ws("crawl_nested");
  // The folder is not named for the package: the crawl matches package.xml's <name>.
  const fs::path package = ws.path() / "src" / "some_repo" / "my_description";
  write_package(package, "my_hand_description");
  // Hidden folders are not walked (".hidden" would come first in name order).
  write_package(ws.path() / "src" / ".hidden" / "copy", "my_hand_description");
  const std::string hand = write_hand_naming(ws.path() / "hand", "my_hand_description");
  ScopedEnv ros("ROS_PACKAGE_PATH", "/nonexistent/ros:" + (ws.path() / "src").string());
  ScopedEnv ament("AMENT_PREFIX_PATH", std::nullopt);
  expect_meshes_from(load_hand(hand), package);
}

TEST(UrdfImportRosPackageCrawl, CatkinIgnoreInTheRepositoryFolderHidesItsPackages) {
  TempDir ws("crawl_catkin_ignore");
  write_package(ws.path() / "src" / "some_repo" / "my_description", "my_hand_description");
  std::ofstream(ws.path() / "src" / "some_repo" / "CATKIN_IGNORE").flush();
  const std::string hand = write_hand_naming(ws.path() / "hand", "my_hand_description");
  const std::string ros_package_path = (ws.path() / "src").string();
  ScopedEnv ros("ROS_PACKAGE_PATH", ros_package_path);
  ScopedEnv ament("AMENT_PREFIX_PATH", std::nullopt);
  const std::string what = load_error(hand);
  EXPECT_EQ(what.rfind("load_hand: '", 0), 0u) << what;
  EXPECT_NE(what.find("package_uri.urdf'"), std::string::npos) << what;
  EXPECT_NE(what.find("ROS package 'my_hand_description' not found (searched package_paths {}, "
                      "ROS_PACKAGE_PATH '" + ros_package_path + "' (0 package.xml), "
                      "AMENT_PREFIX_PATH unset)"),
            std::string::npos)
      << what;
}

TEST(UrdfImportRosPackageCrawl, PackageInsideAPackageIsNotFound) {
  TempDir ws("crawl_nested_package");
  const fs::path outer = ws.path() / "src" / "outer";
  write_package(outer, "outer_package");
  write_package(outer / "inner", "my_hand_description");
  const std::string hand = write_hand_naming(ws.path() / "hand", "my_hand_description");
  ScopedEnv ros("ROS_PACKAGE_PATH", (ws.path() / "src").string());
  ScopedEnv ament("AMENT_PREFIX_PATH", std::nullopt);
  EXPECT_NE(load_error(hand).find("ROS package 'my_hand_description' not found"),
            std::string::npos);
  // The outer package is one: its meshes load.
  expect_meshes_from(load_hand(write_hand_naming(ws.path() / "outer_hand", "outer_package")),
                     outer);
}

TEST(UrdfImportRosPackageCrawl, FirstRosPackagePathDirectoryListingTheNameWins) {
  TempDir first("crawl_first"), second("crawl_second");
  write_package(first.path() / "repo" / "a", "my_hand_description");
  write_package(second.path() / "b", "my_hand_description");
  const std::string hand = write_hand_naming(first.path() / "hand", "my_hand_description");
  ScopedEnv ament("AMENT_PREFIX_PATH", std::nullopt);
  {
    ScopedEnv ros("ROS_PACKAGE_PATH", first.path().string() + ":" + second.path().string());
    expect_meshes_from(load_hand(hand), first.path() / "repo" / "a");
  }
  ScopedEnv ros("ROS_PACKAGE_PATH", second.path().string() + ":" + first.path().string());
  expect_meshes_from(load_hand(hand), second.path() / "b");
}

TEST(UrdfImportRosPackageCrawl, ExplicitPackagePathsComeBeforeTheCrawl) {
  TempDir ws("crawl_explicit_first"), other("crawl_explicit_dir");
  write_package(ws.path() / "src" / "repo" / "my_description", "my_hand_description");
  write_package(other.path(), "some_name");  // the option's directory needs no matching name
  const std::string hand = write_hand_naming(ws.path() / "hand", "my_hand_description");
  ScopedEnv ros("ROS_PACKAGE_PATH", (ws.path() / "src").string());
  ScopedEnv ament("AMENT_PREFIX_PATH", std::nullopt);
  HandLoadOptions options;
  options.package_paths["my_hand_description"] = other.path().string();
  expect_meshes_from(load_hand(hand, options), other.path());
}

TEST(UrdfImportRosPackageCrawl, RosPackagePathComesBeforeAmentPrefixPath) {
  TempDir ws("crawl_before_ament"), prefix("crawl_ament_prefix");
  write_package(ws.path() / "src" / "repo" / "my_description", "my_hand_description");
  write_package(prefix.path() / "share" / "my_hand_description", "my_hand_description");
  const std::string hand = write_hand_naming(ws.path() / "hand", "my_hand_description");
  ScopedEnv ament("AMENT_PREFIX_PATH", prefix.path().string());
  {
    ScopedEnv ros("ROS_PACKAGE_PATH", (ws.path() / "src").string());
    expect_meshes_from(load_hand(hand), ws.path() / "src" / "repo" / "my_description");
  }
  // share/NAME/package.xml makes an installed package (without the ament index marker).
  ScopedEnv ros("ROS_PACKAGE_PATH", std::nullopt);
  expect_meshes_from(load_hand(hand), prefix.path() / "share" / "my_hand_description");
}

TEST(UrdfImportRosPackageCrawl, AmentShareDirectoryWithoutMarkerOrPackageXmlIsNotAPackage) {
  TempDir prefix("ament_bare_share");
  fs::create_directories(prefix.path() / "share" / kPackage / "meshes");
  fs::copy_file(package_dir() / "meshes" / "tetra.obj",
                prefix.path() / "share" / kPackage / "meshes" / "tetra.obj");
  ScopedEnv ros("ROS_PACKAGE_PATH", std::nullopt);
  ScopedEnv ament("AMENT_PREFIX_PATH", prefix.path().string());
  const std::string what = load_error(package_hand());
  EXPECT_NE(what.find("ROS package 'cordgrasp_test_meshes' not found"), std::string::npos) << what;
  EXPECT_NE(what.find("AMENT_PREFIX_PATH '" + prefix.path().string() + "'"), std::string::npos)
      << what;
}

TEST(UrdfImportRosPackageCrawl, SymlinkLoopEndsTheWalkAndThePackageIsFound) {
  TempDir ws("crawl_symlink_loop");
  const fs::path package = ws.path() / "src" / "z_repo" / "my_description";
  write_package(package, "my_hand_description");
  fs::create_directory_symlink(ws.path() / "src", ws.path() / "src" / "a_loop");
  const std::string hand = write_hand_naming(ws.path() / "hand", "my_hand_description");
  ScopedEnv ros("ROS_PACKAGE_PATH", (ws.path() / "src").string());
  ScopedEnv ament("AMENT_PREFIX_PATH", std::nullopt);
  // Either path names the package's meshes; the walk met the real folder first (a_loop is the
  // same directory as src, already walked).
  expect_meshes_from(load_hand(hand), package);
}

TEST(UrdfImportRosPackageCrawl, CrawlIsCachedPerRosPackagePathValue) {
  TempDir ws("crawl_cached");
  const fs::path package = ws.path() / "src" / "repo" / "my_description";
  write_package(package, "my_hand_description");
  const std::string hand = write_hand_naming(ws.path() / "hand", "my_hand_description");
  ScopedEnv ament("AMENT_PREFIX_PATH", std::nullopt);
  ScopedEnv ros("ROS_PACKAGE_PATH", (ws.path() / "src").string());
  expect_meshes_from(load_hand(hand), package);
  // Moved after the first crawl: the same ROS_PACKAGE_PATH still names the old folder.
  fs::rename(package, ws.path() / "src" / "repo" / "moved");
  const std::string what = load_error(hand);
  EXPECT_NE(what.find("mesh file 'package://my_hand_description/meshes/tetra.obj' not found"),
            std::string::npos)
      << what;
  // A different value (a trailing ':') crawls again and finds the package where it is now.
  ScopedEnv again("ROS_PACKAGE_PATH", (ws.path() / "src").string() + ":");
  expect_meshes_from(load_hand(hand), ws.path() / "src" / "repo" / "moved");
}

}  // namespace
}  // namespace cordgrasp
