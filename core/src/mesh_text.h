#pragma once
// Private to core: text helpers shared by the checks load_mesh runs before assimp reads a file.
#include <string>

namespace cordgrasp::detail {

/// A line ends where assimp 5.2's text readers end one: at CR, LF, NUL or FF.
inline bool is_assimp_line_end(char c) {
  return c == '\r' || c == '\n' || c == '\0' || c == '\f';
}

/// Up to 24 characters of file text for a message, bytes outside printable ASCII as '?', "..."
/// after a longer text.
std::string shown_text(const char* begin, const char* end);
std::string shown_text(const std::string& text);
/// shown_text() in single quotes.
std::string quoted_text(const char* begin, const char* end);
std::string quoted_text(const std::string& text);

/// Empty unless the file's first bytes (`head`, `head_bytes` of them) start with FE FF 00 00 or
/// 00 00 FE FF: assimp 5.2 reads these as a UTF-32 byte-order mark in every reader that takes its
/// input as text (STL, both ASCII and binary, OFF, an OBJ's material library), and converts the
/// text reading past its buffer (BaseImporter::ConvertToUTF8; found by fuzzing an ASan build of
/// assimp 5.2.5). Otherwise the problem, one line.
std::string utf32_mark_problem(const unsigned char* head, std::size_t head_bytes);

/// utf32_mark_problem() of the file at `path`'s first bytes; empty if it cannot be read.
std::string file_utf32_mark_problem(const std::string& path);

}  // namespace cordgrasp::detail
