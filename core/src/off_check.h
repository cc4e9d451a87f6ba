#pragma once
// Private to core: what load_mesh checks in an OFF file before assimp reads it.
#include <cstdint>
#include <string>

namespace cordgrasp::detail {

/// Empty if assimp 5.2's OFF reader (which reads every file named .off, with or without the
/// "OFF" keyword) reads the file at `path` as it says; otherwise the problem, one line. The
/// reader sizes its vertex and face arrays by the header's counts before reading a line,
/// overruns a 4096-byte line buffer by one byte, and skips a face of 0 or more than 9 vertices
/// by lowering its face count, which wraps below zero (off_check.cpp follows its header and
/// line rules): counts may not exceed the file's `file_bytes`, and every face line must give
/// 1 to 9 whole-number indices below the vertex count.
std::string off_problem(const std::string& path, std::uintmax_t file_bytes);

}  // namespace cordgrasp::detail
