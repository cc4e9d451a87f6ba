#pragma once
#include <string>

namespace cordgrasp {

/// Writes `bytes` to `path` atomically (temp file beside it + rename): readers never see a
/// half-written file. @throws InputError naming the path on failure.
void write_file_atomically(const std::string& path, const std::string& bytes);

}  // namespace cordgrasp
