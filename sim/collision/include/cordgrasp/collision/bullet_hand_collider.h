#pragma once
#include <memory>

#include "cordgrasp/core/hand_collider.h"
#include "cordgrasp/core/hand_model.h"
#include "cordgrasp/core/mesh.h"

namespace cordgrasp {

/// Collision margins of the Bullet collider [m] (Bullet's 4 cm default is far too large here),
/// and the threads that build it.
struct BulletColliderParams {
  /// Link shapes, shrink-wrapped by it (sim/collision/src/bullet_shapes.h).
  double link_margin_m = 0.5e-3;
  /// Widens the object's bounding box in the broad phase only; the triangles themselves are
  /// queried without margin.
  double object_margin_m = 0.0;
  /// Threads that build the object's BVH (build_object_bvh); the collider does not depend on it.
  int threads = 1;
};

/// HandObjectCollider on Bullet's collision library: link shapes are primitives and
/// shrink-wrapped convex hulls of the URDF collision elements (one compound per link), the
/// object its non-degenerate triangles in core's MeshBvh; queries run GJK/EPA per triangle near
/// the link's oriented boxes (convex-vs-concave, as Bullet's btConvexConcaveCollisionAlgorithm
/// does); docs/finger-stage-and-quality.md. The hand and mesh are copied: the collider keeps
/// no references to them.
/// @throws std::invalid_argument when the mesh has no usable triangle.
std::unique_ptr<HandObjectCollider> make_bullet_hand_collider(
    const HandModel& hand, const Mesh& object, const BulletColliderParams& params = {});

}  // namespace cordgrasp
