#pragma once
#include <Eigen/Core>

#include "cordgrasp/core/finger_stage.h"
#include "cordgrasp/core/grasp_plan.h"
#include "cordgrasp/core/grasp_quality.h"
#include "cordgrasp/core/hand_collider.h"
#include "cordgrasp/core/hand_model.h"
#include "cordgrasp/core/mesh.h"

namespace cordgrasp {

/// What every grasp attempt of one plan shares: the hand's setup and the object's constants.
struct PlanContext {
  HandSetup setup;
  WrenchSpaceObject wrench_object;
  Eigen::Vector3d principal_axis_O = Eigen::Vector3d::UnitZ();
  /// Centre of mass at uniform density (closed volume, else convex hull) and bounding radius r.
  Eigen::Vector3d com_O = Eigen::Vector3d::Zero();
  double radius_m = 0.0;
};

/// The object's constants (everything but `setup`): the part that takes long on a scan of
/// millions of triangles, and needs no collider.
PlanContext object_plan_context(const Mesh& mesh, const PlanParams& params);

/// object_plan_context() and the hand's setup (prepare_hand); `collider` built for this hand
/// and mesh.
PlanContext make_plan_context(const Mesh& mesh, const HandModel& hand, HandObjectCollider& collider,
                              const PlanParams& params);

}  // namespace cordgrasp
