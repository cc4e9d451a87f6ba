#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <memory>
#include <optional>
#include <vector>

#include "cordgrasp/core/mesh_bvh.h"

namespace cordgrasp {

/// Closest points between one hand link and the object, in the object frame
/// (docs/algorithm.md §7.4).
struct LinkObjectProximity {
  double distance_m = 0.0;  ///< signed: > 0 separated, < 0 penetration depth [m]
  Eigen::Vector3d p_link_O = Eigen::Vector3d::Zero();    ///< witness point on the link [m]
  Eigen::Vector3d p_object_O = Eigen::Vector3d::Zero();  ///< witness point on the object [m]
  Eigen::Vector3d n_O = Eigen::Vector3d::UnitZ();  ///< unit normal at p_object, object → link
};

/// Collision and proximity queries between the links of one hand and one rigid object, the seam
/// between the planner (core, no Bullet) and its collision backend (sim, Bullet; see
/// cordgrasp/collision/bullet_hand_collider.h). All poses are in the object frame O: the object
/// sits at the identity. Link indices are HandModel link indices. Queries are kinematic only.
/// Links without collision geometry never collide. Not thread-safe: one instance per thread.
class HandObjectCollider {
 public:
  virtual ~HandObjectCollider() = default;

  /// Number of hand links (HandModel::links.size()).
  virtual int num_links() const = 0;

  /// True when the link has collision geometry.
  virtual bool has_geometry(int link) const = 0;

  /// Sets the pose X_OL of every link (size num_links(), e.g. from link_poses()).
  virtual void set_link_poses(const std::vector<Eigen::Isometry3d>& X_OL) = 0;

  /// Sets the pose X_OL of one link.
  virtual void set_link_pose(int link, const Eigen::Isometry3d& X_OL) = 0;

  /// True when the link's geometry touches or penetrates the object surface (distance < 0).
  /// Surface-based: a link entirely inside a closed object without crossing its surface is not
  /// reported.
  virtual bool link_collides_with_object(int link) = 0;

  /// True when the geometries of two links overlap (distance < 0).
  virtual bool links_collide(int link_a, int link_b) = 0;

  /// Cheap conservative lower bound on the link–object distance [m] (e.g. bounding volumes):
  /// the true distance is at least this; may be ≤ 0 near the object; +inf without geometry.
  /// Lets callers skip steps that cannot collide.
  virtual double link_object_distance_lower_bound(int link) = 0;

  /// Closest points between the link and the object when their distance is at most
  /// `max_distance_m` (penetrating pairs included, with negative distance); nullopt otherwise.
  virtual std::optional<LinkObjectProximity> link_object_proximity(int link,
                                                                   double max_distance_m) = 0;

  /// The object's BVH (build_object_bvh) when the collider keeps one, for the cord exploration
  /// to share instead of building its own; nullptr otherwise.
  virtual std::shared_ptr<const MeshBvh> object_bvh() const { return nullptr; }
};

}  // namespace cordgrasp
