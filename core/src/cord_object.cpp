#include "cordgrasp/core/cord_object.h"

#include <stdexcept>

#include "cordgrasp/core/mesh_properties.h"

namespace cordgrasp {

CordObject make_cord_object(const Mesh& mesh, std::shared_ptr<const MeshBvh> bvh) {
  if (mesh.triangles.empty())
    throw std::invalid_argument("make_cord_object: mesh '" + mesh.name + "' has no triangles");
  CordObject obj;
  obj.bvh = bvh ? std::move(bvh) : std::make_shared<const MeshBvh>(build_object_bvh(mesh));
  obj.center = vertex_mean(mesh);
  obj.radius_m = bounding_radius(mesh, obj.center);
  return obj;
}

}  // namespace cordgrasp
