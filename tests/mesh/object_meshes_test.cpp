#include "cordgrasp/core/object_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "cordgrasp/core/convex_hull_volume.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/core/mesh_topology.h"
#include "cordgrasp/core/mesh_volume.h"
#include "cordgrasp/core/orient_triangles.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

constexpr double kSizeTol_m = 0.001;  ///< shipped sizes are stated to the millimetre
constexpr double kFloatTol_m = 1e-8;  ///< assimp parses OBJ coordinates as float
constexpr int kMinTriangles = 200;
constexpr int kMaxTriangles = 4000;

struct Expected {
  Eigen::Vector3d size_m;
  bool closed;
  int components;
  int euler;
};

const std::map<std::string, Expected>& expected_objects() {
  static const std::map<std::string, Expected> table{
      {"box", {{0.050, 0.050, 0.080}, true, 1, 2}},
      {"long_cylinder", {{0.035, 0.035, 0.250}, true, 1, 2}},
      {"sphere", {{0.060, 0.060, 0.060}, true, 1, 2}},
      {"bottle", {{0.070, 0.070, 0.220}, true, 1, 2}},
      {"mug", {{0.113, 0.080, 0.095}, true, 2, 4}},
      {"wine_glass", {{0.084, 0.084, 0.200}, true, 1, 2}},
      {"torus", {{0.104, 0.104, 0.024}, true, 1, 0}},
      {"pliers", {{0.198, 0.083, 0.017}, true, 7, 14}},
      {"kettle", {{0.193, 0.120, 0.155}, true, 3, 6}},
      {"defective", {{0.075, 0.075, 0.060}, false, 1, 1}},
  };
  return table;
}

std::string shipped_path(const std::string& name) {
  return test::source_dir() + "/assets/objects/" + name + ".obj";
}

TEST(ObjectMeshes, NamesListEveryObjectAndMugIsTheDefault) {
  EXPECT_EQ(shipped_object_names().size(), expected_objects().size());
  for (const auto& name : shipped_object_names()) EXPECT_EQ(expected_objects().count(name), 1u);
  EXPECT_EQ(default_object_name(), "mug");
  EXPECT_THROW(make_object_mesh("teapot"), std::invalid_argument);
}

TEST(ObjectMeshes, EveryShippedObjectLoadsWithItsSizeAndTopologyClass) {
  for (const auto& name : shipped_object_names()) {
    SCOPED_TRACE(name);
    MeshLoadReport report;
    const Mesh m = load_mesh(shipped_path(name), {}, &report);
    const Expected& e = expected_objects().at(name);
    EXPECT_EQ(report.degenerate_dropped, 0);
    EXPECT_GE(int(m.triangles.size()), name == "defective" ? 300 : kMinTriangles);
    EXPECT_LE(int(m.triangles.size()), kMaxTriangles);
    const Aabb box = mesh_bounds(m);
    EXPECT_LT((box.size() - e.size_m).cwiseAbs().maxCoeff(), kSizeTol_m) << box.size().transpose();
    EXPECT_NEAR(box.min.z(), 0.0, kFloatTol_m);  // resting on z = 0
    const MeshTopology t = mesh_topology(m);
    EXPECT_EQ(t.closed, e.closed);
    EXPECT_EQ(t.components, e.components);
    EXPECT_EQ(t.euler_characteristic, e.euler);
  }
}

TEST(ObjectMeshes, ShippedFilesMatchTheGeneratorUpToFloatParsing) {
  for (const auto& name : shipped_object_names()) {
    SCOPED_TRACE(name);
    const Mesh generated = make_object_mesh(name);
    const Mesh loaded = load_mesh(shipped_path(name));
    ASSERT_EQ(loaded.triangles.size(), generated.triangles.size());
    ASSERT_EQ(loaded.vertices.size(), generated.vertices.size());  // no accidental welds
    double worst = 0.0;
    for (size_t t = 0; t < loaded.triangles.size(); ++t)
      for (int k = 0; k < 3; ++k)
        worst = std::max(worst, (loaded.vertices[loaded.triangles[t][k]] -
                                 generated.vertices[generated.triangles[t][k]])
                                    .norm());
    EXPECT_LT(worst, kFloatTol_m);
  }
}

TEST(ObjectMeshes, ClosedObjectsFaceOutwardAndHaveAVolumeInsideTheirHull) {
  for (const auto& name : shipped_object_names()) {
    if (name == "defective") continue;
    SCOPED_TRACE(name);
    Mesh m = make_object_mesh(name);
    const MeshTopology t = mesh_topology(m);
    EXPECT_EQ(t.misoriented_edges, 0);
    const auto solid = closed_mesh_volume(m);
    ASSERT_TRUE(solid.has_value());
    const SolidVolume hull = convex_hull_volume(m);
    EXPECT_GT(solid->volume_m3, 0.0);
    EXPECT_LE(solid->volume_m3, hull.volume_m3 * (1 + 1e-9));
    EXPECT_EQ(orient_triangles(m).flipped, 0);  // the generator already winds outward
  }
}

TEST(ObjectMeshes, EveryObjectHasAGraspableWidthForAnSahSizedHand) {
  // The planner needs a front cord with ξ in 1.5–7.5 cm, about half the width the hand closes
  // on: some extent of the object must lie in 3–15 cm, and none may exceed a hand-held 26 cm.
  for (const auto& name : shipped_object_names()) {
    SCOPED_TRACE(name);
    const Eigen::Vector3d size = mesh_bounds(make_object_mesh(name)).size();
    EXPECT_TRUE(((size.array() >= 0.03) && (size.array() <= 0.15)).any()) << size.transpose();
    EXPECT_LE(size.maxCoeff(), 0.26);
  }
}

TEST(ObjectMeshes, LongCylinderPrincipalAxisIsItsAxis) {
  const PrincipalAxes pa = principal_axes(make_long_cylinder_object());
  EXPECT_NEAR(std::abs(pa.axes.col(0).z()), 1.0, 1e-9);
}

TEST(ObjectMeshes, SphereBarycenterAndRadiusAreExact) {
  const Mesh m = make_sphere_object();
  const Eigen::Vector3d c = vertex_mean(m);
  EXPECT_LT((c - Eigen::Vector3d(0, 0, 0.03)).norm(), 1e-9);
  EXPECT_NEAR(bounding_radius(m, c), 0.03, 1e-7);  // coordinates are rounded to 0.1 µm
}

TEST(ObjectMeshes, MugVolumeMatchesItsWallsAndHandle) {
  // Oracle from the parameters: shell = outer solid − cavity (48-gon prisms), handle ≈ tube.
  const MugObjectParams p;
  const auto prism = [](double r, double h) {
    return 0.5 * 48 * r * r * std::sin(2 * M_PI / 48) * h;
  };
  const double shell = prism(0.5 * p.outer_diameter_m, p.height_m) -
                       prism(0.5 * p.outer_diameter_m - p.wall_m, p.height_m - p.bottom_m);
  const auto v = closed_mesh_volume(make_mug_object(p));
  ASSERT_TRUE(v.has_value());
  const double handle = v->volume_m3 - shell;
  // Handle: a tube of radius 5.5 mm along ~half an ellipse (~0.1 m) plus its short ends.
  EXPECT_GT(handle, M_PI * 0.0055 * 0.0055 * 0.08);
  EXPECT_LT(handle, M_PI * 0.0055 * 0.0055 * 0.13);
}

TEST(ObjectMeshes, DefectiveObjectIsOpenNonManifoldAndHasFlippedFaces) {
  const MeshTopology t = mesh_topology(load_mesh(shipped_path("defective")));
  EXPECT_FALSE(t.closed);
  EXPECT_EQ(t.boundary_edges, 24 + 3);  // open top rim + the fin's free edges
  EXPECT_EQ(t.non_manifold_edges, 1);
  EXPECT_EQ(t.misoriented_edges, 9);  // three flipped faces, three edges each
  EXPECT_FALSE(closed_mesh_volume(load_mesh(shipped_path("defective"))).has_value());
}

}  // namespace
}  // namespace cordgrasp
