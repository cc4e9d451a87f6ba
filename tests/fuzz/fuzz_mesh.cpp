// Fuzz target: bytes as a mesh file -> load_mesh -> what `cordgrasp info --object` computes
// (topology, bounds, principal axes, volumes).
//
// The file is named as a user's would be, by what it holds (mesh_file_name): PLY, OFF and ASCII
// STL by their first word, binary bytes as binary STL, any other text as OBJ. One load per
// input: assimp's OBJ reader zero-fills a 16 MB buffer per file, which under ASan (fresh pages
// each time) made the four-extensions-per-input version run at ~50 inputs/s.
#include <cstdint>
#include <cstring>

#include "cordgrasp/core/convex_hull_volume.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/core/mesh_topology.h"
#include "cordgrasp/core/mesh_volume.h"
#include "fuzz_input_file.h"

using namespace cordgrasp;

namespace {

bool starts_with_word(const uint8_t* data, size_t size, const char* word) {
  size_t i = 0;
  while (i < size && (data[i] == ' ' || data[i] == '\t' || data[i] == '\r' || data[i] == '\n'))
    ++i;
  const size_t n = std::strlen(word);
  return size - i >= n && std::memcmp(data + i, word, n) == 0;
}

const char* mesh_file_name(const uint8_t* data, size_t size) {
  if (starts_with_word(data, size, "ply")) return "mesh.ply";
  for (const char* off : {"OFF", "COFF", "NOFF", "CNOFF", "STOFF", "4OFF", "nOFF"})
    if (starts_with_word(data, size, off)) return "mesh.off";
  if (starts_with_word(data, size, "solid")) return "mesh.stl";
  if (size >= 84)  // binary STL: an 80-byte header, a face count, 50 bytes per face
    for (size_t i = 0; i < size; ++i)
      if ((data[i] < 0x20 && data[i] != '\t' && data[i] != '\n' && data[i] != '\r') ||
          data[i] >= 0x7f)
        return "mesh.stl";
  return "mesh.obj";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const fuzz::FuzzInputFile file(mesh_file_name(data, size), data, size);
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
  return 0;
}
