#pragma once
// Private to core: what load_mesh checks in a PLY file before assimp reads it.
#include <cstdint>
#include <string>

namespace cordgrasp::detail {

/// Empty if the file at `path` does not start like PLY or passes; otherwise the problem, one
/// line. assimp 5.2's PLY reader never returns from a header without "end_header", and sizes
/// its arrays from counts in the file before reading what they count: an element count in the
/// header, a list's count in the body (ASCII: its leading digits, as assimp reads them; binary:
/// a count type wider than a byte). No count may exceed the file's `file_bytes`, or a list's
/// count the bytes left after it.
std::string ply_problem(const std::string& path, std::uintmax_t file_bytes);

}  // namespace cordgrasp::detail
