#pragma once
#include <functional>
#include <ostream>
#include <string>

namespace cordgrasp {

/// Writes `bytes` to `path` atomically (temp file beside it + rename): readers never see a
/// half-written file. @throws InputError naming the path on failure.
void write_file_atomically(const std::string& path, const std::string& bytes);

/// As above, with the contents written by `write` into the temporary file's stream (a large
/// file without a copy of it in memory). An exception from `write` removes the temporary file.
void write_file_atomically(const std::string& path,
                           const std::function<void(std::ostream&)>& write);

}  // namespace cordgrasp
