#include "mesh_text.h"

#include <fstream>

namespace cordgrasp::detail {

std::string shown_text(const char* begin, const char* end) {
  std::string text;
  for (const char* c = begin; c != end && c != begin + 24; ++c)
    text += (*c >= 0x20 && *c < 0x7f) ? *c : '?';
  return text + (end - begin > 24 ? "..." : "");
}
std::string shown_text(const std::string& text) {
  return shown_text(text.data(), text.data() + text.size());
}
std::string quoted_text(const char* begin, const char* end) {
  return "'" + shown_text(begin, end) + "'";
}
std::string quoted_text(const std::string& text) { return "'" + shown_text(text) + "'"; }

std::string utf32_mark_problem(const unsigned char* head, std::size_t head_bytes) {
  if (head_bytes < 4) return {};
  const bool little = head[0] == 0xFE && head[1] == 0xFF && head[2] == 0 && head[3] == 0;
  const bool big = head[0] == 0 && head[1] == 0 && head[2] == 0xFE && head[3] == 0xFF;
  if (!little && !big) return {};
  return std::string("starts with the bytes ") + (little ? "FE FF 00 00" : "00 00 FE FF") +
         ", which assimp 5.2 takes for a UTF-32 byte-order mark and then reads past its buffer "
         "(save text as ASCII or UTF-8; a binary STL needs another 80-byte header)";
}

std::string file_utf32_mark_problem(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char head[4] = {};
  in.read(reinterpret_cast<char*>(head), sizeof head);
  return utf32_mark_problem(head, static_cast<std::size_t>(in.gcount()));
}

}  // namespace cordgrasp::detail
