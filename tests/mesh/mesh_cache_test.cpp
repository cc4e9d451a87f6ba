// load_mesh's on-disk cache (MeshLoadOptions::cache_folder).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/mesh_properties.h"
#include "test_files.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

namespace fs = std::filesystem;

/// The cache's entries (*.mesh) in `folder`.
std::vector<fs::path> entries(const fs::path& folder) {
  std::vector<fs::path> out;
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().extension() == ".mesh") out.push_back(it->path());
  return out;
}

/// Options caching every file (a test mesh is far below the default threshold) in `folder`.
MeshLoadOptions caching_in(const fs::path& folder) {
  MeshLoadOptions o;
  o.cache_folder = folder.string();
  o.cache_min_file_bytes = 0;
  return o;
}

void expect_same(const Mesh& a, const Mesh& b) {
  EXPECT_EQ(a.name, b.name);
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  ASSERT_EQ(a.triangles.size(), b.triangles.size());
  for (size_t i = 0; i < a.vertices.size(); ++i) EXPECT_EQ(a.vertices[i], b.vertices[i]);
  for (size_t i = 0; i < a.triangles.size(); ++i) EXPECT_EQ(a.triangles[i], b.triangles[i]);
}

/// A copy of the test file in `dir` (so that the test may change it).
std::string copy_of(const test::TempDir& dir, const std::string& test_file) {
  const std::string path = dir.file(fs::path(test_file).filename().string());
  fs::copy_file(test::test_data(test_file), path);
  return path;
}

TEST(MeshCache, TheSecondLoadIsReadFromTheCacheAndIsTheFileLoadToTheBit) {
  const test::TempDir dir;
  const fs::path cache = dir.path / "cache";
  for (const std::string file : {"meshes/some_degenerate.obj", "meshes/box_100mm.obj",
                                 "meshes/formats/box.ply", "meshes/formats/box_binary.stl"}) {
    SCOPED_TRACE(file);
    MeshLoadOptions options = caching_in(cache);
    options.units = LengthUnits::kAuto;
    MeshLoadReport plain_report, first, second;
    const Mesh plain = load_mesh(test::test_data(file), {options.units}, &plain_report);
    const Mesh loaded = load_mesh(test::test_data(file), options, &first);
    const Mesh cached = load_mesh(test::test_data(file), options, &second);
    EXPECT_FALSE(first.from_cache);
    EXPECT_TRUE(second.from_cache);
    expect_same(plain, loaded);
    expect_same(plain, cached);
    EXPECT_EQ(second.degenerate_dropped, plain_report.degenerate_dropped);
    EXPECT_EQ(second.scale_to_m, plain_report.scale_to_m);
    EXPECT_EQ(second.auto_chose_mm, plain_report.auto_chose_mm);
  }
  EXPECT_EQ(entries(cache).size(), 4u);
}

TEST(MeshCache, TheFilesBytesAndTheLoadOptionsKeyTheEntry) {
  const test::TempDir dir;
  const fs::path cache = dir.path / "cache";
  const std::string path = copy_of(dir, "meshes/formats/box.obj");
  MeshLoadOptions options = caching_in(cache);
  MeshLoadReport report;
  load_mesh(path, options, &report);
  options.scale = 2.0;
  const Mesh twice = load_mesh(path, options, &report);
  EXPECT_FALSE(report.from_cache);
  EXPECT_EQ(entries(cache).size(), 2u);
  EXPECT_EQ(mesh_bounds(twice).size().x(), 2.0 * mesh_bounds(load_mesh(path)).size().x());
  // The same name, other bytes: the file is read again, not the entry of the old bytes.
  std::ofstream(path, std::ios::app) << "v 5 5 5\nv 6 5 5\nv 5 6 5\nf 9 10 11\n";
  const Mesh grown = load_mesh(path, options, &report);
  EXPECT_FALSE(report.from_cache);
  EXPECT_EQ(grown.triangles.size(), 13u);
  EXPECT_EQ(entries(cache).size(), 3u);
}

TEST(MeshCache, ACorruptOrTruncatedEntryIsNotUsedAndIsReplaced) {
  const test::TempDir dir;
  const fs::path cache = dir.path / "cache";
  const std::string path = test::test_data("meshes/formats/box.ply");
  const MeshLoadOptions options = caching_in(cache);
  const Mesh plain = load_mesh(path, options);
  ASSERT_EQ(entries(cache).size(), 1u);
  const fs::path entry = entries(cache)[0];
  const auto size = fs::file_size(entry);
  for (int damage = 0; damage < 3; ++damage) {
    SCOPED_TRACE(damage);
    if (damage == 0) {  // one bit of a coordinate flipped
      std::fstream f(entry, std::ios::in | std::ios::out | std::ios::binary);
      f.seekp(std::streamoff(size / 2));
      char c = 0;
      f.read(&c, 1);
      f.seekp(std::streamoff(size / 2));
      f.put(char(c ^ 1));
    } else if (damage == 1) {
      fs::resize_file(entry, size - 5);
    } else {
      std::ofstream(entry, std::ios::binary) << "not a mesh";
    }
    MeshLoadReport report;
    expect_same(load_mesh(path, options, &report), plain);
    EXPECT_FALSE(report.from_cache);
    EXPECT_EQ(fs::file_size(entry), size);  // written again
    load_mesh(path, options, &report);
    EXPECT_TRUE(report.from_cache);
  }
}

TEST(MeshCache, AFolderThatCannotBeMadeLeavesTheLoadAsItIs) {
  const test::TempDir dir;
  const std::string not_a_folder = dir.write("file.txt", "a file, not a folder");
  const MeshLoadOptions options = caching_in(fs::path(not_a_folder) / "cache");
  MeshLoadReport report;
  expect_same(load_mesh(test::test_data("meshes/formats/box.off"), options, &report),
              load_mesh(test::test_data("meshes/formats/box.off")));
  EXPECT_FALSE(report.from_cache);
}

TEST(MeshCache, SmallFilesAndFormatsThatReadOtherFilesAreNotCached) {
  const test::TempDir dir;
  const fs::path cache = dir.path / "cache";
  MeshLoadOptions options;
  options.cache_folder = cache.string();  // default threshold: far above the test files
  load_mesh(test::test_data("meshes/formats/box.obj"), options);
  EXPECT_TRUE(entries(cache).empty());
  options.cache_min_file_bytes = 0;
  load_mesh(test::test_data("meshes/formats/box.gltf"), options);
  load_mesh(test::test_data("meshes/formats/box_zup.dae"), options);
  EXPECT_TRUE(entries(cache).empty());
}

TEST(MeshCache, EntriesBeyondTheBoundGoLeastRecentlyUsedFirst) {
  const test::TempDir dir;
  const fs::path cache = dir.path / "cache";
  MeshLoadOptions options = caching_in(cache);
  const std::string box = test::test_data("meshes/formats/box.obj");
  const std::string other = test::test_data("meshes/some_degenerate.obj");
  load_mesh(box, options);
  ASSERT_EQ(entries(cache).size(), 1u);
  const fs::path box_entry = entries(cache)[0];
  options.cache_max_bytes = fs::file_size(box_entry) + 1;  // room for one such entry
  load_mesh(other, options);
  const std::vector<fs::path> left = entries(cache);
  ASSERT_EQ(left.size(), 1u);
  EXPECT_NE(left[0], box_entry);  // the older one went
  MeshLoadReport report;
  load_mesh(other, options, &report);
  EXPECT_TRUE(report.from_cache);
}

}  // namespace
}  // namespace cordgrasp
