#pragma once
// sim-internal: the object as a dynamic btRigidBody (docs/physics.md §2): a convex hull, a HACD
// compound or a btGImpactMeshShape; mass from density × volume, inertia from the collision shape;
// the body frame C is the principal inertia frame at the centre of mass.
#include <BulletCollision/Gimpact/btGImpactShape.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <btBulletCollisionCommon.h>

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "cordgrasp/core/mesh.h"
#include "cordgrasp/sim/sim_params.h"
#include "cordgrasp/sim/sim_result.h"

namespace cordgrasp::bullet {

struct ObjectBody {
  SimObjectInfo info;
  std::string mesh_key;  ///< mesh_hash of the mesh it was built from
  Eigen::Isometry3d X_OC = Eigen::Isometry3d::Identity();  ///< body frame in object frame
  std::vector<std::unique_ptr<btConvexHullShape>> hulls;   ///< parts, points in C
  std::unique_ptr<btCompoundShape> compound;               ///< several parts
  std::vector<btScalar> vertices;                          ///< GImpact vertex array (C)
  std::vector<int> indices;                                ///< GImpact triangles
  std::unique_ptr<btTriangleIndexVertexArray> mesh_interface;
  std::unique_ptr<btGImpactMeshShape> gimpact;
  btCollisionShape* shape = nullptr;  ///< the one the body uses
  std::unique_ptr<btRigidBody> body;
};

/// Mass properties of a uniform solid of density 1 bounded by outward-oriented triangles.
struct UnitSolid {
  double volume_m3 = 0.0;
  Eigen::Vector3d com = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  ///< about com, per unit density
};

/// Volume integrals over closed, consistently oriented triangles (signed tetrahedra).
UnitSolid unit_solid(const std::vector<Eigen::Vector3d>& vertices,
                     const std::vector<Eigen::Vector3i>& triangles);

/// The solid convex hull of points (btConvexHullComputer); empty for flat input.
UnitSolid convex_hull_solid(const std::vector<Eigen::Vector3d>& points);

/// Returns compute()'s value for `key`, computing it once per key and process (concurrent
/// callers of one key wait for the first). A validate of N grasps or trials builds N bodies of
/// one object: what depends on the mesh alone (hulls of millions of vertices) is derived once.
template <typename T, typename F>
const T& once_per_key(const std::string& key, F&& compute) {
  struct Entry {
    std::once_flag once;
    T value;
  };
  static std::mutex mutex;
  static std::map<std::string, std::unique_ptr<Entry>> entries;
  Entry* entry = nullptr;
  {
    const std::lock_guard<std::mutex> lock(mutex);
    std::unique_ptr<Entry>& slot = entries[key];
    if (!slot) slot = std::make_unique<Entry>();
    entry = slot.get();
  }
  std::call_once(entry->once, [&]() { entry->value = compute(); });
  return entry->value;
}

/// Flat index list (3 per triangle) of the mesh's triangles of non-zero area: Bullet's
/// triangle shapes want no degenerate ones.
std::vector<int> area_triangle_indices(const Mesh& mesh);

/// Builds the object body at the identity pose. @throws std::invalid_argument for a mesh
/// without usable triangles.
std::unique_ptr<ObjectBody> make_object_body(const Mesh& mesh, const SimParams& params);

}  // namespace cordgrasp::bullet
