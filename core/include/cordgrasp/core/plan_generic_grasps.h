#pragma once
#include <Eigen/Core>
#include <random>

#include "cordgrasp/core/cancel_token.h"
#include "cordgrasp/core/grasp_plan.h"
#include "cordgrasp/core/hand_collider.h"
#include "cordgrasp/core/hand_model.h"
#include "cordgrasp/core/mesh.h"
#include "cordgrasp/core/plan_context.h"

namespace cordgrasp {

/// Outward unit normal of triangle `tri` at point `p_O` on it: the winding normal, flipped when
/// a ray from p along it crosses the soup an odd number of times (it points into the object).
/// Ray parity is right for closed meshes whatever their winding, concave ones included.
Eigen::Vector3d outward_face_normal(const Mesh& mesh, int tri, const Eigen::Vector3d& p_O);

/// The same normal with the object's vertex mean and its bounding radius about it given, and
/// its BVH (the same ray hits in logarithmic time; null: every triangle is tested).
Eigen::Vector3d outward_face_normal(const Mesh& mesh, int tri, const Eigen::Vector3d& p_O,
                                    const Eigen::Vector3d& vertex_mean_O, double radius_m,
                                    const MeshBvh* bvh);

/// Baseline like Simox GenericGraspPlanner + ApproachMovementSurfaceNormal (paper §V): random
/// surface point (area-weighted), GCP there with +z along the inward normal and a uniform random
/// roll, retreat until collision-free, close, force-closure check; repeated until params.grasps
/// force-closure grasps, the time limit or params.max_attempts. Seeded by params.seed.
/// `cancel` is checked before each attempt (PlanStats::interrupted). `context`: the hand's and
/// object's constants when the caller keeps them (make_plan_context() with this hand, mesh and
/// collider), else built here.
PlanResult plan_generic_grasps(const Mesh& mesh, const HandModel& hand,
                               HandObjectCollider& collider, const PlanParams& params,
                               const CancelToken& cancel = {},
                               const PlanContext* context = nullptr);

}  // namespace cordgrasp
