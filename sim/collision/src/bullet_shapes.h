#pragma once
// Internal to cordgrasp::collision and cordgrasp::sim (target cordgrasp_collision_internal):
// HandModel geometry → Bullet collision shapes. One construction shared by the planner's
// collider (bullet_hand_collider.cpp) and the physics model, so planning and physics see the
// very same geometry. Bullet types stay out of public headers.
#include <btBulletCollisionCommon.h>

#include <memory>
#include <vector>

#include "cordgrasp/core/hand_model.h"

namespace cordgrasp::bullet {

/// Shape construction parameters. Bullet's 4 cm default margin is far too large at hand scale.
struct ShapeParams {
  /// Margin of link shapes [m]. Hulls are shrunk by it first (btConvexHullComputer), boxes and
  /// cylinders keep it inside their extents, spheres are all margin: the margin-inflated shape
  /// matches the authored geometry up to rounded hull edges of this radius.
  double link_margin_m = 0.5e-3;
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
  std::vector<Eigen::Isometry3d> X_LC;  ///< child frames in the link frame (F: make_links_shape)
};

/// Builds the LinkShape of `link` (compound is nullptr when it has no usable geometry).
LinkShape make_link_shape(const Link& link, const ShapeParams& params = {});

/// One compound for several links rigidly joined (fixed joints merged into one body, as the
/// physics does): link i's elements sit at X_FL[i]·X_LG in the common frame F. The same child
/// shapes as make_link_shape. @throws std::invalid_argument when the sizes differ.
LinkShape make_links_shape(const std::vector<const Link*>& links,
                           const std::vector<Eigen::Isometry3d>& X_FL,
                           const ShapeParams& params = {});

/// Shrink-wrapped convex hull of points (as link meshes get): hull vertices inset so every face
/// moves in by about `margin_m` (at most a fifth of the smallest extent), that margin set on
/// the shape, so hull + margin ≈ the points' hull. nullptr for < 4 points or a flat hull.
std::unique_ptr<btConvexHullShape> make_convex_hull_shape(
    const std::vector<Eigen::Vector3d>& points, double margin_m);

}  // namespace cordgrasp::bullet
