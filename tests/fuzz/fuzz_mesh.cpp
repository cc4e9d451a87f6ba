// Fuzz target: bytes as a mesh file of each format -> load_mesh -> what `cordgrasp info
// --object` computes (topology, bounds, principal axes, volumes).
#include <cstdint>

#include "cordgrasp/core/convex_hull_volume.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/core/mesh_topology.h"
#include "cordgrasp/core/mesh_volume.h"
#include "fuzz_input_file.h"

using namespace cordgrasp;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  for (const char* name : {"mesh.obj", "mesh.stl", "mesh.ply", "mesh.off"}) {
    const fuzz::FuzzInputFile file(name, data, size);
    fuzz::expect_input_errors([&] {
      MeshLoadOptions options;
      options.units = LengthUnits::kAuto;
      const Mesh mesh = load_mesh(file.path(), options);
      mesh_topology(mesh);
      mesh_bounds(mesh);
      bounding_radius(mesh, vertex_mean(mesh));
      principal_axes(mesh);
      closed_mesh_volume(mesh);
      convex_hull_volume(mesh);
    });
  }
  return 0;
}
