#pragma once
#include <cstdint>
#include <string>

#include "cordgrasp/core/mesh.h"

namespace cordgrasp {

/// Length units of a mesh file; converted to meters at load.
enum class LengthUnits { kMeters, kMillimeters, kAuto };

/// "m", "mm", "auto".
const char* to_string(LengthUnits units);

/// Parses "m", "mm" or "auto". @throws std::invalid_argument otherwise.
LengthUnits parse_length_units(const std::string& text);

struct MeshLoadOptions {
  LengthUnits units = LengthUnits::kMeters;  ///< units of the file's coordinates
  double auto_mm_diagonal = 5.0;  ///< kAuto picks mm when the bbox diagonal exceeds this [file units]
  double scale = 1.0;  ///< uniform factor applied after the unit conversion, about the origin (> 0)
  /// Folder of the mesh cache (empty: none): an OBJ, STL, PLY or OFF file of at least
  /// `cache_min_file_bytes` is kept there once loaded, in binary, keyed by its bytes and these
  /// options, and read from there the next time. Beyond `cache_max_bytes` in all, the least
  /// recently used entries are removed.
  std::string cache_folder;
  std::uintmax_t cache_min_file_bytes = std::uintmax_t(16) << 20;
  std::uintmax_t cache_max_bytes = std::uintmax_t(2) << 30;
};

/// What load_mesh did besides loading.
struct MeshLoadReport {
  int degenerate_dropped = 0;  ///< zero-area or repeated-index triangles removed
  double scale_to_m = 1.0;     ///< factor applied to the file's coordinates (units × scale)
  bool auto_chose_mm = false;  ///< kAuto decided the file was in millimeters
  bool from_cache = false;     ///< read from options.cache_folder
};

/// Loads OBJ, STL (ascii/binary), PLY, OFF, DAE or glTF via assimp as a triangle soup in meters.
/// Keeps the soup as authored (no normal fixing or re-winding); only vertices at identical
/// coordinates are shared. Node transforms are applied; for DAE, `<unit>` is applied and the
/// up-axis rotation is not (as ROS/RViz). Degenerate triangles (repeated corner, or altitude
/// below 1e-7 of the bounding-box diagonal, i.e. zero at float precision) are dropped and
/// counted in `report`. A cached mesh is the one loading the file gives, to the bit.
/// @throws InputError "load_mesh: '<path>': <problem>" for a missing/unreadable/empty file,
///         unknown format, zero triangles, NaN/inf coordinates or all-degenerate geometry,
///         a face without vertices or indexing past them, a PLY header without "end_header"
///         or with an element count above the file size;
///         std::invalid_argument when options.scale is not finite and > 0.
Mesh load_mesh(const std::string& path, const MeshLoadOptions& options = {},
               MeshLoadReport* report = nullptr);

/// Writes the mesh as Wavefront OBJ (meters, 9 significant digits), atomically (temp + rename).
/// @throws InputError when the file cannot be written.
void save_mesh_obj(const Mesh& mesh, const std::string& path);

}  // namespace cordgrasp
