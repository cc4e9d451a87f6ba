#pragma once
// Private to core: what load_mesh checks in a PLY file before assimp reads it.
#include <cstdint>
#include <string>

namespace cordgrasp::detail {

/// Empty if assimp would not take the file at `path` for PLY (its first line does not start
/// with "ply"), or if assimp 5.2 reads it as its header says; otherwise the problem, one line.
/// assimp's PLY reader never returns from a header without "end_header", sizes its arrays from
/// counts in the file before reading what they count, and reads some files otherwise than the
/// format says (ply_check.cpp lists how): counts may not exceed the file's `file_bytes` (a
/// list's, the values on its line or the bytes left), and files the two would read
/// differently are refused.
std::string ply_problem(const std::string& path, std::uintmax_t file_bytes);

}  // namespace cordgrasp::detail
