#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <set>

#include "cordgrasp/core/convex_hull_volume.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/core/mesh_topology.h"
#include "cordgrasp/core/mesh_volume.h"
#include "manifest.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

constexpr double kManifestSizeTol_m = 0.0006;  ///< MANIFEST bboxes are rounded to 1 mm
constexpr size_t kManifestObjects = 38;

TEST(MeshDataset, EveryObjectFileIsInTheManifest) {
  CORDGRASP_REQUIRE_SHARED_DATA();
  std::set<std::string> listed;
  for (const auto& o : test::manifest_objects()) listed.insert(o.file);
  EXPECT_EQ(listed.size(), kManifestObjects);
  namespace fs = std::filesystem;
  const fs::path root = test::shared_data_dir();
  int meshes = 0;
  for (const auto& e : fs::recursive_directory_iterator(root / "objects")) {
    const std::string ext = e.path().extension().string();
    if (ext != ".obj" && ext != ".stl" && ext != ".STL" && ext != ".ply" && ext != ".off" &&
        ext != ".dae" && ext != ".gltf")
      continue;
    ++meshes;
    EXPECT_EQ(listed.count(fs::relative(e.path(), root).string()), 1u) << e.path();
  }
  EXPECT_EQ(meshes, int(kManifestObjects));
}

TEST(MeshDataset, EveryObjectLoadsWithTheManifestTriangleCountsAndTopology) {
  CORDGRASP_REQUIRE_SHARED_DATA();
  const auto objects = test::manifest_objects();
  ASSERT_EQ(objects.size(), kManifestObjects);
  int dropped_total = 0;
  for (const auto& o : objects) {
    SCOPED_TRACE(o.file);
    MeshLoadReport report;
    const Mesh m = load_mesh(test::shared_data_dir() + "/" + o.file, {}, &report);
    dropped_total += report.degenerate_dropped;
    if (report.degenerate_dropped > 0)
      std::cout << o.file << ": " << report.degenerate_dropped << " degenerate dropped\n";
    EXPECT_EQ(int(m.triangles.size()) + report.degenerate_dropped, o.triangles);
    EXPECT_LT((mesh_bounds(m).size() - o.size_m).cwiseAbs().maxCoeff(), kManifestSizeTol_m);
    const MeshTopology t = mesh_topology(m);
    EXPECT_EQ(t.closed, o.watertight);
    EXPECT_EQ(t.boundary_edges, o.boundary_edges);
    EXPECT_EQ(t.non_manifold_edges, o.non_manifold_edges);
    EXPECT_EQ(t.components, o.components);
    EXPECT_EQ(t.euler_characteristic, o.euler_characteristic);
    // Volume exactly when watertight, and never more than the convex hull.
    const auto solid = closed_mesh_volume(m);
    EXPECT_EQ(solid.has_value(), o.watertight);
    const SolidVolume hull = convex_hull_volume(m);
    EXPECT_GT(hull.volume_m3, 0.0);
    if (solid) {
      EXPECT_LE(solid->volume_m3, hull.volume_m3 * (1 + 1e-9));
    }
  }
  RecordProperty("degenerate_dropped", dropped_total);
  EXPECT_EQ(dropped_total, 0);  // the staged objects have no degenerate triangles
}

}  // namespace
}  // namespace cordgrasp
