#pragma once
// sim-internal: HandModel / Mesh geometry → Bullet collision shapes. One construction shared by
// the planner's collider (bullet_hand_collider.cpp) and the physics model, so planning and
// physics see the very same geometry. Bullet types stay out of public headers.
#include <btBulletCollisionCommon.h>

#include <memory>
#include <vector>

#include "cordgrasp/core/hand_model.h"
#include "cordgrasp/core/mesh.h"

namespace cordgrasp::bullet {

/// Collision margins. Bullet's 4 cm default is far too large at hand scale.
struct ShapeParams {
  /// Margin of link shapes [m]. Hulls are shrunk by it first (btConvexHullComputer), boxes and
  /// cylinders keep it inside their extents, spheres are all margin: the margin-inflated shape
  /// matches the authored geometry up to rounded hull edges of this radius.
  double link_margin_m = 0.5e-3;
  /// Margin of the object's triangles [m]; it inflates the object surface (0 = exact).
  double object_margin_m = 0.0;
};

inline btVector3 to_bt(const Eigen::Vector3d& v) { return btVector3(v.x(), v.y(), v.z()); }
inline Eigen::Vector3d from_bt(const btVector3& v) { return {v.x(), v.y(), v.z()}; }
btTransform to_bt(const Eigen::Isometry3d& X);
Eigen::Isometry3d from_bt(const btTransform& X);

/// Convex shape of one URDF collision element, in its geometry frame G: btBoxShape,
/// btCylinderShapeZ, btSphereShape, or the shrink-wrapped convex hull (btConvexHullShape) of a
/// mesh — a non-convex mesh is replaced by its hull. nullptr for an empty or degenerate mesh.
std::unique_ptr<btConvexShape> make_geometry_shape(const Geometry& geometry,
                                                   const ShapeParams& params = {});

/// Collision shape of one link: a btCompoundShape with one convex child per URDF <collision>
/// element at its X_LG (so multi-element links and offsets work alike). Owns its children.
struct LinkShape {
  std::unique_ptr<btCompoundShape> compound;  ///< nullptr when the link has no collision geometry
  std::vector<std::unique_ptr<btConvexShape>> children;  ///< child i of `compound`
  std::vector<Eigen::Isometry3d> X_LC;                   ///< child frames in the link frame
};

/// Builds the LinkShape of `link` (compound is nullptr when it has no usable geometry).
LinkShape make_link_shape(const Link& link, const ShapeParams& params = {});

/// The object as a static concave triangle mesh (btBvhTriangleMeshShape over a copy of the
/// soup; zero-area triangles dropped). Owns the vertex/index arrays Bullet points into.
struct ObjectMeshShape {
  std::vector<btScalar> vertices;  ///< xyz triples [m]
  std::vector<int> indices;        ///< triangle index triples
  std::unique_ptr<btTriangleIndexVertexArray> mesh_interface;
  std::unique_ptr<btBvhTriangleMeshShape> shape;  ///< nullptr when no triangle is usable
  int dropped_triangles = 0;                      ///< degenerate triangles left out
};

/// Builds the object's BVH triangle-mesh shape (object frame = mesh frame).
std::unique_ptr<ObjectMeshShape> make_object_mesh_shape(const Mesh& mesh,
                                                        const ShapeParams& params = {});

}  // namespace cordgrasp::bullet
