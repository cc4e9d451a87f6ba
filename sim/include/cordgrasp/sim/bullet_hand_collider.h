#pragma once
#include <memory>

#include "cordgrasp/core/hand_collider.h"
#include "cordgrasp/core/hand_model.h"
#include "cordgrasp/core/mesh.h"

namespace cordgrasp {

/// Collision margins of the Bullet collider [m] (Bullet's 4 cm default is far too large here).
struct BulletColliderParams {
  double link_margin_m = 0.5e-3;  ///< link shapes, shrink-wrapped (see sim/src/bullet_shapes.h)
  double object_margin_m = 0.0;   ///< object triangles (inflates the object surface)
};

/// HandObjectCollider on Bullet's collision library: link shapes are primitives and
/// shrink-wrapped convex hulls of the URDF collision elements (one compound per link), the
/// object a btBvhTriangleMeshShape; queries run GJK/EPA per triangle overlapping the link's
/// AABB (convex-vs-concave, as Bullet's btConvexConcaveCollisionAlgorithm does). The hand and
/// mesh are copied: the collider does not keep references to them.
/// @throws std::invalid_argument when the mesh has no usable triangle.
std::unique_ptr<HandObjectCollider> make_bullet_hand_collider(
    const HandModel& hand, const Mesh& object, const BulletColliderParams& params = {});

}  // namespace cordgrasp
