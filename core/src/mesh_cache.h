#pragma once
// Private to core: load_mesh's on-disk cache of large meshes (MeshLoadOptions::cache_folder).
#include <cstdint>
#include <optional>
#include <string>

#include "cordgrasp/core/mesh.h"
#include "cordgrasp/core/mesh_io.h"

namespace cordgrasp::detail {

/// The cache file for `path` loaded with `options`: "<folder>/<key>.mesh", the key hashing the
/// file's bytes, its size, the options and the cache format; empty when the file cannot be read.
std::string mesh_cache_file(const std::string& path, const MeshLoadOptions& options);

/// The mesh and report stored in `file`, or nothing when it is missing, truncated, corrupt or
/// another key's (file name collisions included). Marks the file as just used.
std::optional<Mesh> read_cached_mesh(const std::string& file, MeshLoadReport& report);

/// Stores the mesh and report in `file` (atomically), then removes the folder's least recently
/// used entries until they take at most `max_bytes`. Best effort: a folder that cannot be
/// created or written leaves the cache empty, without error.
void write_cached_mesh(const std::string& file, const Mesh& mesh, const MeshLoadReport& report,
                       std::uintmax_t max_bytes);

}  // namespace cordgrasp::detail
