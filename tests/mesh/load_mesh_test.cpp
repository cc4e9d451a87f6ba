#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <array>
#include <atomic>
#include <chrono>
#include <fstream>
#include <thread>
#include <sstream>
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

using NamedFiles = std::vector<std::pair<std::string, std::string>>;  ///< (file name, bytes)

/// Writes each file into a fresh folder and expects it to load with the given counts.
void expect_each_loads(const NamedFiles& files, size_t triangles, size_t vertices) {
  const test::TempDir dir;
  for (const auto& [name, content] : files) {
    SCOPED_TRACE(name);
    const Mesh m = load_mesh(dir.write(name, content));
    EXPECT_EQ(m.triangles.size(), triangles);
    EXPECT_EQ(m.vertices.size(), vertices);
  }
}

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

// PLY as writers produce it: comments, obj_info, CRLF line ends, tabs, exponents, int list
// counts, both byte orders. The checks before assimp's reader must let all of them through.
TEST(LoadMesh, PlyVariantsWritersProduceLoadTheBox) {
  const std::string text = test::read_text(test::test_data("meshes/formats/box.ply"));
  const std::string header_end = "end_header\n";
  const size_t body_at = text.find(header_end) + header_end.size();
  const std::string header = text.substr(0, body_at), body = text.substr(body_at);
  auto replaced = [](std::string s, const std::string& from, const std::string& to) {
    for (size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
      s.replace(at, from.size(), to);
    return s;
  };
  NamedFiles files{
      {"crlf.ply", replaced(text, "\n", "\r\n")},
      {"comments.ply",
       replaced(header, "comment",
                "comment TextureFile box.png\nobj_info scanner 1\ncomment vertex colors 0\n"
                "comment 0 faces\ncomment") +
           body},
      {"tabs_exponents.ply", header + replaced(replaced(body, " ", "\t"), "0.055", "5.5e-2")},
      {"int_counts.ply", replaced(header, "list uchar int", "list int uint") + body},
      // assimp ends a line at a CR too, and skips one blank line.
      {"cr_and_blank_line.ply", header + replaced(replaced(body, "\n4 0 2", "\n\n4 0 2"), "0.01 0.02 0.055\n", "0.01 0.02 0.055\r")},
  };
  // Binary, both byte orders, counts as uint.
  std::vector<float> points;
  std::vector<std::vector<int>> faces;
  {
    std::istringstream in(body);
    for (int v = 0; v < 8; ++v)
      for (int k = 0; k < 3; ++k) points.push_back(0), in >> points.back();
    // Moved by 1 m: 0.01 as a float starts with the byte 0x0A, which assimp skips (refused
    // below).
    for (float& p : points) p += 1.0f;
    for (int f = 0; f < 6; ++f) {
      int n = 0;
      in >> n;
      faces.emplace_back(n);
      for (int& i : faces.back()) in >> i;
    }
  }
  for (const bool big : {false, true}) {
    std::string bytes = "ply\nformat binary_" + std::string(big ? "big" : "little") +
                        "_endian 1.0\nelement vertex 8\nproperty float x\nproperty float y\n"
                        "property float z\nelement face 6\nproperty list uint int "
                        "vertex_indices\nend_header\n";
    auto put = [&bytes, big](const void* value) {
      char b[4];
      std::memcpy(b, value, 4);
      if (big) std::reverse(b, b + 4);
      bytes.append(b, 4);
    };
    for (const float& p : points) put(&p);
    for (const auto& f : faces) {
      const uint32_t n = uint32_t(f.size());
      put(&n);
      for (const int& i : f) put(&i);
    }
    files.emplace_back(big ? "big_endian.ply" : "little_endian.ply", bytes);
    if (!big) {  // a CRLF header: assimp skips the LF, so a body may start with the byte 0x0A
      const float x = 0.01f;  // its first byte is 0x0A
      bytes.replace(bytes.find("end_header\n"), 11, "end_header\r\n");
      std::memcpy(&bytes[bytes.find("end_header\r\n") + 12], &x, 4);
      files.emplace_back("crlf_header_body_starts_with_lf.ply", bytes);
    }
  }
  expect_each_loads(files, 12, 8);
}

// PLY that assimp 5.2 would read otherwise than its header says (and then size an array by a
// count from the wrong bytes), or with a count it would allocate before reading: refused, one
// line naming the problem.
TEST(LoadMesh, PlyFilesAssimpWouldMisreadAreRefused) {
  const std::string head =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\n";
  const std::string vertices = "0 0 0\n1 0 0\n0 1 0\n";
  const std::vector<BadInput> cases{
      {head + "property list uchar int vertex_indices\nend_header\n" + vertices + "3000000000 0 1 2\n",
       "PLY line 13: element 'face' entry 0 lists '3000000000' values, more than the 3 on its line"},
      {head + "property list int int vertex_indices\nend_header\n" + vertices + "-3 0 1 2\n",
       "PLY line 13: '-3' is not a list count (element 'face' entry 0)"},
      {head + "property list float int vertex_indices\nend_header\n" + vertices + "3 0 1 2\n",
       "PLY line 8: a list's count type must be an integer type, not 'float'"},
      {"ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\nend_header\n"
       "\n\x01\x02\x03",
       "a binary PLY body starting with a line-feed byte (0x0A) after \"end_header\\n\": assimp "
       "5.2 drops it and would read every value a byte late"},
      {head + "property list uchar int vertex_indices\nend_header\n0 0 0\n\n\n1 0 0\n0 1 0\n3 0 1 2\n",
       "PLY line 12: blank where element 'vertex' entry 1 should be"},
      {head + "property list uchar int vertex_indices\nend_header\n0 0 0\n" + std::string(1, '\0') +
           " 9 9\n1 0 0\n0 1 0\n",
       "PLY file ends before element 'face' entry 0 (of 1)"},
      {head + "property list  uchar int vertex_indices\nend_header\n" + vertices + "3 0 1 2\n",
       "PLY line 8: more than one space after 'list'"},
      {head + "property list uchar int vertex_indices\ncomment made by hand\nproperty float w\n"
              "end_header\n" + vertices + "3 0 1 2 0\n",
       "PLY line 10: a property after a comment or a blank line (assimp 5.2 ends the element's "
       "properties there)"},
      {"ply\nformat ascii 1.0\nelement camera 1\nproperty float x\n" + head.substr(19) +
           "end_header\n0\n" + vertices,
       "PLY line 3: element 'camera': assimp 5.2 reads the entries of vertex, face, tristrips, "
       "edge and material elements only (it would take these for none and misread the rest)"},
      {"ply\nformat ascii 1.0\ncomment 2 lines skipped\n" + head.substr(19) +
           "property list uchar int vertex_indices\nend_header\n" + vertices + "3 0 1 2\n",
       "PLY line 3: a comment assimp would read as an element of '2' entries"},
      {"ply\nformat ascii 1.0\ncomment face 1 more\n" + head.substr(19) +
           "property list uchar int vertex_indices\nend_header\n" + vertices + "3 0 1 2\n",
       "PLY line 3: a comment assimp would read as an element of '1' entries"},
      {head + "property fl0at w\nproperty list uchar int vertex_indices\nend_header\n" + vertices +
           "0 3 0 1 2\n",
       "PLY line 8: unknown property type 'fl0at'"},
      {head + "element face 1\nend_header\n", "PLY line 8: element 'face' defined twice"},
      {head + "property list uchar int vertex_indices\n", "PLY header without an 'end_header' line"},
      {head + "property list uchar int vertex_indices\nend_header\n0 0 x\n1 0 0\n0 1 0\n3 0 1 2\n",
       "PLY line 10: 'x' is not a float (element 'vertex' entry 0)"},
  };
  const test::TempDir dir;
  int k = 0;
  for (const BadInput& c : cases) {
    SCOPED_TRACE(c.file);
    const std::string path = dir.write("bad" + std::to_string(k++) + ".ply", c.file);
    const std::string msg = load_error(path);
    EXPECT_EQ(msg, "load_mesh: '" + path + "': " + c.problem);
  }
}

// OFF as writers produce it (assimp 5.2 reads any file named .off with its OFF reader).
TEST(LoadMesh, OffVariantsLoadTheTetrahedron) {
  const std::string points = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  const std::string faces = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  const NamedFiles files{
      {"plain.off", "OFF\n4 4 6\n" + points + faces},
      {"comments_crlf.off", "OFF\r\n# a comment\r\n4 4 6 # counts\r\n\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n"
                            "0 0 1\r\n3 0 2 1\r\n3 0 1 3\r\n3 0 3 2\r\n3 1 2 3\r\n"},
      {"dimension.off", "nOFF 3\n4 4 6\n" + points + faces},
      {"face_colors.off", "OFF\n4 4 6\n" + points +
                              "3 0 2 1 255 0 0\n3 0 1 3 0 255 0\n3 0 3 2 0 0 255\n3 1 2 3 9 9 9\n"},
  };
  expect_each_loads(files, 4, 4);
  const test::TempDir dir;
  // Without the keyword; a count starting with 4 would be read as the homogeneous prefix.
  EXPECT_EQ(load_mesh(dir.write("no_keyword.off", "3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"))
                .triangles.size(),
            1u);
  const std::string path = dir.write("no_keyword_4.off", "4 4 6\n" + points + faces);
  EXPECT_EQ(load_error(path), "load_mesh: '" + path +
                                  "': an OFF file without the 'OFF' keyword whose first count "
                                  "starts with 4 (assimp 5.2 reads it as a prefix; add an 'OFF' "
                                  "line)");
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
