#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <array>
#include <atomic>
#include <chrono>
#include <fstream>
#include <thread>
#include <string>
#include <vector>

#include "cordgrasp/core/error.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/core/mesh_topology.h"
#include "cordgrasp/core/mesh_volume.h"
#include "test_files.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

constexpr double kFloatTol_m = 1e-8;  ///< assimp reads coordinates (and DAE matrices) as float

/// The InputError message of load_mesh(path), or "" when it loads.
std::string load_error(const std::string& path, const MeshLoadOptions& options = {}) {
  try {
    load_mesh(path, options);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

struct BadInput {
  std::string file;
  std::string problem;  ///< expected part of the message
};

TEST(LoadMesh, ThrowsWithPathWhenFileMissing) {
  const std::string path = test::test_data("meshes/no_such_mesh.obj");
  const std::string msg = load_error(path);
  EXPECT_EQ(msg, "load_mesh: '" + path + "': file not found");
}

TEST(LoadMesh, EveryBadInputFileGivesOneLineNamingFileAndProblem) {
  const std::vector<BadInput> cases{
      {"unknown_format.xyz", "unknown mesh format '.xyz'"},
      {"empty.obj", "empty file (0 bytes)"},
      {"only_vertices.obj", "0 triangles (no faces in the file)"},
      {"nan_coordinate.obj", "NaN/inf vertex coordinate (0, nan, 0) in 3 triangle(s)"},
      {"inf_coordinate.obj", "NaN/inf vertex coordinate (0, 0, inf) in 3 triangle(s)"},
      {"all_degenerate.obj", "all 3 triangles are degenerate (zero area)"},
  };
  for (const BadInput& c : cases) {
    SCOPED_TRACE(c.file);
    const std::string path = test::test_data("meshes/" + c.file);
    const std::string msg = load_error(path);
    EXPECT_EQ(msg.rfind("load_mesh: '" + path + "': ", 0), 0u) << msg;
    EXPECT_NE(msg.find(c.problem), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  }
}

// `mtllib ../secret.mtl` names a FIFO outside the mesh's folder: opening it would block until a
// writer comes. A guard thread plays the writer (a non-blocking open for writing succeeds only
// while someone has the FIFO open for reading), so an opened FIFO is seen, not a hang.
TEST(LoadMesh, MaterialFilesOutsideTheMeshFolderAreNotOpenedAndTheGeometryLoads) {
  const test::TempDir dir;
  std::filesystem::create_directories(dir.path / "mesh");
  const std::string fifo = dir.file("secret.mtl"), obj = dir.file("mesh/escape.obj");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::ofstream(obj) << "mtllib ../secret.mtl\nv 0 0 0\nv 0.1 0 0\nv 0 0.1 0\nv 0 0 0.1\n"
                        "usemtl secret\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  std::atomic<bool> done{false}, opened{false};
  std::thread writer([&] {
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (!done && std::chrono::steady_clock::now() < until) {
      const int fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK);
      if (fd >= 0) {  // a reader has it open: let it read an empty file
        opened = true;
        ::close(fd);
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  });
  ::testing::internal::CaptureStderr();
  Mesh mesh;
  EXPECT_NO_THROW(mesh = load_mesh(obj));
  const std::string err = ::testing::internal::GetCapturedStderr();
  done = true;
  writer.join();
  EXPECT_FALSE(opened) << "load_mesh opened " << fifo;
  EXPECT_EQ(mesh.triangles.size(), 4u);
  EXPECT_NE(err.find("not opening '"), std::string::npos) << err;
  EXPECT_NE(err.find("secret.mtl': outside the mesh's folder"), std::string::npos) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
}

TEST(LoadMesh, MaterialFilesBesideTheMeshAreReadWithoutAWarning) {
  ::testing::internal::CaptureStderr();
  const Mesh mesh = load_mesh(test::test_data("robustness/meshes/mtllib/inside.obj"));
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  EXPECT_EQ(mesh.triangles.size(), 12u);
}

TEST(LoadMesh, DirectoryIsRejected) {
  EXPECT_NE(load_error(test::test_data("meshes")).find("is a directory"), std::string::npos);
}

TEST(LoadMesh, DropsAndCountsDegenerateTrianglesIncludingFloatRoundedCollinearOnes) {
  MeshLoadReport report;
  const Mesh m = load_mesh(test::test_data("meshes/some_degenerate.obj"), {}, &report);
  EXPECT_EQ(report.degenerate_dropped, 3);
  EXPECT_EQ(m.triangles.size(), 4u);
  EXPECT_EQ(m.vertices.size(), 4u);  // vertices only used by dropped triangles are removed
  EXPECT_TRUE(mesh_topology(m).closed);
}

TEST(LoadMesh, MillimeterBoxIsScaledByMmAndDetectedByAuto) {
  const std::string path = test::test_data("meshes/box_100mm.obj");
  const Eigen::Vector3d size_m(0.1, 0.08, 0.06);
  MeshLoadReport report;
  MeshLoadOptions options;
  options.units = LengthUnits::kAuto;
  Mesh m = load_mesh(path, options, &report);
  EXPECT_TRUE(report.auto_chose_mm);
  EXPECT_EQ(report.scale_to_m, 1e-3);
  EXPECT_TRUE(mesh_bounds(m).size().isApprox(size_m, 1e-12));

  options.units = LengthUnits::kMillimeters;
  m = load_mesh(path, options, &report);
  EXPECT_FALSE(report.auto_chose_mm);
  EXPECT_TRUE(mesh_bounds(m).size().isApprox(size_m, 1e-12));

  options.units = LengthUnits::kMeters;
  m = load_mesh(path, options, &report);
  EXPECT_EQ(report.scale_to_m, 1.0);
  EXPECT_TRUE(mesh_bounds(m).size().isApprox(1000 * size_m, 1e-12));
}

TEST(LoadMesh, ScaleMultipliesAfterTheUnitsAndMustBePositive) {
  const std::string path = test::test_data("meshes/box_100mm.obj");
  MeshLoadOptions options;
  options.units = LengthUnits::kMillimeters;
  options.scale = 2.0;
  MeshLoadReport report;
  const Mesh m = load_mesh(path, options, &report);
  EXPECT_EQ(report.scale_to_m, 2e-3);
  EXPECT_TRUE(mesh_bounds(m).size().isApprox(Eigen::Vector3d(0.2, 0.16, 0.12), 1e-12));
  for (double bad : {0.0, -1.0, std::nan("")}) {
    options.scale = bad;
    EXPECT_THROW(load_mesh(path, options), std::invalid_argument) << bad;
  }
}

TEST(LoadMesh, AutoUnitsKeepMetersForAMeterScaleMesh) {
  MeshLoadReport report;
  MeshLoadOptions options;
  options.units = LengthUnits::kAuto;
  load_mesh(test::test_data("meshes/formats/box.obj"), options, &report);
  EXPECT_FALSE(report.auto_chose_mm);
  EXPECT_EQ(report.scale_to_m, 1.0);
}

TEST(LoadMesh, ParsesUnitNames) {
  EXPECT_EQ(parse_length_units("m"), LengthUnits::kMeters);
  EXPECT_EQ(parse_length_units("mm"), LengthUnits::kMillimeters);
  EXPECT_EQ(parse_length_units("auto"), LengthUnits::kAuto);
  EXPECT_THROW(parse_length_units("cm"), std::invalid_argument);
}

// ---- Format coverage: the same box in every format (tests/data/meshes/formats/make_formats.py).

/// The reference box: x in [0.01, 0.03], y in [-0.01, 0.02], z in [0.005, 0.055], outward.
Mesh reference_box() {
  const Eigen::Vector3d lo(0.01, -0.01, 0.005), hi(0.03, 0.02, 0.055);
  Mesh m;
  for (int i = 0; i < 8; ++i)
    m.vertices.emplace_back((i & 1) ? hi.x() : lo.x(), (i & 2) ? hi.y() : lo.y(),
                            (i & 4) ? hi.z() : lo.z());
  m.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                 {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return m;
}

/// Index of the reference vertex within kFloatTol_m of p, or -1.
int match_vertex(const Mesh& ref, const Eigen::Vector3d& p) {
  for (size_t i = 0; i < ref.vertices.size(); ++i)
    if ((ref.vertices[i] - p).norm() < kFloatTol_m) return int(i);
  return -1;
}

/// Triangle as reference indices rotated so the smallest comes first (keeps the winding).
std::array<int, 3> canonical(std::array<int, 3> t) {
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

TEST(LoadMesh, EveryFormatLoadsTheSameOrientedBox) {
  const Mesh ref = reference_box();
  std::vector<std::array<int, 3>> want;
  for (const auto& t : ref.triangles) want.push_back(canonical({t[0], t[1], t[2]}));
  std::sort(want.begin(), want.end());
  const std::vector<std::string> files{
      "box.obj", "box_ascii.stl", "box_binary.stl",      "box.ply",
      "box.off", "box_zup.dae",   "box_zup_unit_mm.dae", "box.gltf"};
  for (const std::string& file : files) {
    SCOPED_TRACE(file);
    MeshLoadReport report;
    const Mesh m = load_mesh(test::test_data("meshes/formats/" + file), {}, &report);
    EXPECT_EQ(report.degenerate_dropped, 0);
    ASSERT_EQ(m.triangles.size(), 12u);
    EXPECT_EQ(m.vertices.size(), 8u);  // STL's per-facet vertices are welded
    std::vector<std::array<int, 3>> got;
    for (const auto& t : m.triangles) {
      std::array<int, 3> r;
      for (int k = 0; k < 3; ++k) {
        r[k] = match_vertex(ref, m.vertices[t[k]]);
        ASSERT_GE(r[k], 0) << "vertex " << m.vertices[t[k]].transpose() << " is not a box corner";
      }
      got.push_back(canonical(r));
    }
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got, want);  // same triangles with the same winding
    const auto v = closed_mesh_volume(m);
    ASSERT_TRUE(v.has_value());
    EXPECT_NEAR(v->volume_m3, 0.02 * 0.03 * 0.05, 1e-6 * 0.02 * 0.03 * 0.05);  // float input
  }
}

TEST(LoadMesh, ColladaUpAxisIsIgnoredButNodeTransformsAreApplied) {
  // box_zup.dae stores the box in a child node's frame: rotated 90° about z under a translated
  // parent. Applying assimp's Z_UP → Y_UP root rotation would swap y and z.
  const Aabb box = mesh_bounds(load_mesh(test::test_data("meshes/formats/box_zup.dae")));
  EXPECT_LT((box.min - Eigen::Vector3d(0.01, -0.01, 0.005)).norm(), kFloatTol_m);
  EXPECT_LT((box.max - Eigen::Vector3d(0.03, 0.02, 0.055)).norm(), kFloatTol_m);
}

}  // namespace
}  // namespace cordgrasp
