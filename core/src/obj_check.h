#pragma once
// Private to core: what load_mesh checks in an OBJ file before assimp reads it.
#include <string>

namespace cordgrasp::detail {

/// Empty if assimp 5.2's OBJ reader reads the file at `path` within its buffers; otherwise the
/// problem, one line. On a face, line or point statement (a line starting with f, l or p), a
/// vertex token with an index after a third '/' makes the reader skip to its line's end and
/// then step one index further, reading past its line buffer (found by fuzzing with an ASan
/// build of assimp 5.2.5; ObjFileParser::getFace, reportErrorTokenInFace).
std::string obj_problem(const std::string& path);

}  // namespace cordgrasp::detail
