#pragma once
#include <Eigen/Core>
#include <memory>

#include "cordgrasp/core/finger_stage.h"
#include "cordgrasp/core/grasp_plan.h"
#include "cordgrasp/core/grasp_quality.h"
#include "cordgrasp/core/hand_collider.h"
#include "cordgrasp/core/hand_model.h"
#include "cordgrasp/core/mesh.h"
#include "cordgrasp/core/mesh_bvh.h"
#include "cordgrasp/core/winding_number.h"

namespace cordgrasp {

/// What every grasp attempt of one plan shares: the hand's setup and the object's constants.
struct PlanContext {
  HandSetup setup;
  WrenchSpaceObject wrench_object;
  Eigen::Vector3d principal_axis_O = Eigen::Vector3d::UnitZ();
  /// Centre of mass at uniform density (closed volume, else convex hull) and bounding radius r.
  Eigen::Vector3d com_O = Eigen::Vector3d::Zero();
  double radius_m = 0.0;
  /// A closed mesh's winding numbers: a contact touched from inside the solid is no grasp
  /// (docs/algorithm.md §7.4). Null for an open mesh, whose inside is not defined.
  std::shared_ptr<const WindingNumberTree> solid;
};

/// The object's constants (everything but `setup`): the part that takes long on a scan of
/// millions of triangles, and needs no collider. `bvh`: the object's BVH (build_object_bvh) to
/// share, e.g. the collider's; built here when null and the mesh is closed.
PlanContext object_plan_context(const Mesh& mesh, const PlanParams& params,
                                std::shared_ptr<const MeshBvh> bvh = nullptr);

/// object_plan_context() and the hand's setup (prepare_hand); `collider` built for this hand
/// and mesh.
PlanContext make_plan_context(const Mesh& mesh, const HandModel& hand, HandObjectCollider& collider,
                              const PlanParams& params);

}  // namespace cordgrasp
