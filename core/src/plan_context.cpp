#include "cordgrasp/core/plan_context.h"

#include <optional>

#include "cordgrasp/core/convex_hull_volume.h"
#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/core/mesh_volume.h"

namespace cordgrasp {

PlanContext object_plan_context(const Mesh& mesh, const PlanParams& params,
                                std::shared_ptr<const MeshBvh> bvh) {
  PlanContext ctx;
  ctx.wrench_object = prepare_wrench_space(mesh, params.quality);
  ctx.principal_axis_O = principal_axes(mesh).axes.col(0);
  const std::optional<SolidVolume> closed = closed_mesh_volume(mesh);
  ctx.com_O = closed ? closed->center_of_mass_m : convex_hull_volume(mesh).center_of_mass_m;
  ctx.radius_m = bounding_radius(mesh, vertex_mean(mesh));
  if (closed) {
    if (!bvh) bvh = std::make_shared<const MeshBvh>(build_object_bvh(mesh));
    ctx.solid = std::make_shared<const WindingNumberTree>(build_winding_number_tree(bvh));
  }
  return ctx;
}

PlanContext make_plan_context(const Mesh& mesh, const HandModel& hand, HandObjectCollider& collider,
                              const PlanParams& params) {
  PlanContext ctx = object_plan_context(mesh, params, collider.object_bvh());
  ctx.setup = prepare_hand(hand, collider);
  return ctx;
}

}  // namespace cordgrasp
