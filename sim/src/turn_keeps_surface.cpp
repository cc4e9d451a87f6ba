#include "cordgrasp/sim/turn_keeps_surface.h"

#include <BulletCollision/CollisionShapes/btBvhTriangleMeshShape.h>
#include <BulletCollision/CollisionShapes/btTriangleCallback.h>
#include <BulletCollision/CollisionShapes/btTriangleIndexVertexArray.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/sim/convex_decomposition.h"
#include "object_body.h"

namespace cordgrasp {

/// The object's triangles and probe points, object frame; Bullet's quantized tree over the
/// triangles is built on the first turn_keeps_surface() (most objects never turn that far).
struct ObjectSurface {
  std::vector<btScalar> vertices;
  std::vector<int> indices;
  std::vector<Eigen::Vector3d> probes;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  ///< area-weighted [m]
  mutable std::once_flag tree_once;
  mutable std::unique_ptr<btTriangleIndexVertexArray> triangles;
  mutable std::unique_ptr<btBvhTriangleMeshShape> tree;

  const btBvhTriangleMeshShape& shape() const {
    std::call_once(tree_once, [this]() {
      triangles = std::make_unique<btTriangleIndexVertexArray>(
          static_cast<int>(indices.size() / 3), const_cast<int*>(indices.data()), 3 * sizeof(int),
          static_cast<int>(vertices.size() / 3), const_cast<btScalar*>(vertices.data()),
          3 * sizeof(btScalar));
      tree = std::make_unique<btBvhTriangleMeshShape>(triangles.get(), true);
    });
    return *tree;
  }
};

namespace {

/// Vertices of the mesh tested per turn: enough to see a turn of any shape, few enough for a
/// test every step while an object spins.
constexpr size_t kProbePoints = 128;

std::unique_ptr<ObjectSurface> build_surface(const Mesh& mesh) {
  auto s = std::make_unique<ObjectSurface>();
  s->indices = bullet::area_triangle_indices(mesh);
  std::vector<bool> used(mesh.vertices.size(), false);
  for (const int i : s->indices) used[static_cast<size_t>(i)] = true;
  if (s->indices.empty())
    throw std::invalid_argument("object_surface: mesh '" + mesh.name +
                                "' has no triangle with an area");
  s->vertices.reserve(3 * mesh.vertices.size());
  for (const Eigen::Vector3d& v : mesh.vertices)
    for (int k = 0; k < 3; ++k) s->vertices.push_back(static_cast<btScalar>(v[k]));
  s->centroid = principal_axes(mesh).centroid;
  std::vector<size_t> used_ids;
  for (size_t i = 0; i < used.size(); ++i)
    if (used[i]) used_ids.push_back(i);
  const size_t n = std::min(kProbePoints, used_ids.size());
  for (size_t k = 0; k < n; ++k)
    s->probes.push_back(mesh.vertices[used_ids[k * used_ids.size() / n]]);
  return s;
}

}  // namespace

const ObjectSurface& object_surface(const Mesh& mesh) {
  return object_surface(mesh, mesh_hash(mesh));
}

const ObjectSurface& object_surface(const Mesh& mesh, const std::string& mesh_key) {
  return *bullet::once_per_key<std::unique_ptr<ObjectSurface>>(
      mesh_key, [&]() { return build_surface(mesh); });
}

namespace {

/// Finds whether any triangle the tree hands it lies within `tolerance` of `point`.
class NearTriangle : public btTriangleCallback {
 public:
  NearTriangle(const btVector3& point, btScalar tolerance)
      : point_(point), tolerance2_(tolerance * tolerance) {}
  void processTriangle(btVector3* triangle, int, int) override {
    if (found) return;
    btSubSimplexClosestResult closest;
    closest.reset();
    solver_.closestPtPointTriangle(point_, triangle[0], triangle[1], triangle[2], closest);
    if ((closest.m_closestPointOnSimplex - point_).length2() <= tolerance2_) found = true;
  }
  bool found = false;

 private:
  btVector3 point_;
  btScalar tolerance2_;
  btVoronoiSimplexSolver solver_;
};

}  // namespace

bool turn_keeps_surface(const ObjectSurface& s, const Eigen::Matrix3d& R_O, double tolerance_m) {
  const btVector3 margin(tolerance_m, tolerance_m, tolerance_m);
  for (const Eigen::Vector3d& p : s.probes) {
    const Eigen::Vector3d q = s.centroid + R_O * (p - s.centroid);
    const btVector3 point(q.x(), q.y(), q.z());
    NearTriangle near(point, static_cast<btScalar>(tolerance_m));
    s.shape().processAllTriangles(&near, point - margin, point + margin);
    if (!near.found) return false;
  }
  return true;
}

}  // namespace cordgrasp
