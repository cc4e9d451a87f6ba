#include "off_check.h"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <vector>

#include "mesh_text.h"

// The rules below follow the OFF reader of assimp 5.2.5 (Debian 12's libassimp5; its source:
// code/AssetLib/OFF/OFFLoader.cpp, include/assimp/ParsingUtils.h, BaseImporter::TextFileToBuffer),
// read, not copied.

namespace cordgrasp::detail {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// Walks a NUL-terminated copy of the file as the reader does.
struct Cursor {
  const char* at;
  const char* end;  // the terminating NUL

  void skip_spaces() {
    while (*at == ' ' || *at == '\t') ++at;
  }
  void skip_spaces_and_line_ends() {
    while (*at == ' ' || *at == '\t' || *at == '\r' || *at == '\n') ++at;
  }
  // Blanks, line ends and comment lines ("#" where a token would start).
  void next_token() {
    skip_spaces_and_line_ends();
    while (at < end && (*at == '#' || *at == '\n' || *at == '\r')) {
      while (*at != '\r' && *at != '\n' && *at != '\0') ++at;
      while (*at == '\r' || *at == '\n') ++at;
      skip_spaces_and_line_ends();
    }
  }
  // The leading digits at the cursor (consumed), as text.
  std::string digits() {
    const char* begin = at;
    while (is_digit(*at)) ++at;
    return std::string(begin, at);
  }
};

// A count's digits as a number, saturating past any file size.
unsigned long long count_value(const std::string& digits) {
  return digits.empty() ? 0 : digits.size() > 18 ? ~0ull : std::stoull(digits);
}

// The digits as assimp's strtoul10 reads them: a 32-bit unsigned that wraps.
uint32_t wrapped_value(const std::string& digits) {
  uint32_t value = 0;
  for (char d : digits) value = value * 10u + uint32_t(d - '0');
  return value;
}

}  // namespace

std::string off_problem(const std::string& path, std::uintmax_t file_bytes) {
  std::ifstream in(path, std::ios::binary);
  std::vector<char> data{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (data.size() < 8) return {};  // the reader refuses it ("File is too small")
  const auto byte = [&data](size_t k) { return static_cast<unsigned char>(data[k]); };
  // The reader converts UTF-16 text (some of it wrongly) and drops a UTF-8 BOM (load_mesh
  // refuses a UTF-32 mark before, for every reader: mesh_text.h).
  if ((byte(0) == 0xFF && byte(1) == 0xFE) || (byte(0) == 0xFE && byte(1) == 0xFF))
    return "OFF text in UTF-16 or UTF-32 (save it as ASCII or UTF-8)";
  if (byte(0) == 0xEF && byte(1) == 0xBB && byte(2) == 0xBF) data.erase(data.begin(), data.begin() + 3);
  data.push_back('\0');
  Cursor c{data.data(), data.data() + data.size() - 1};

  // The header: optional ST, C, N, 4, n prefixes, "OFF" (optional), a dimension after "n",
  // then the vertex, face and edge counts; each read as the leading digits of its token.
  c.next_token();
  const char* const first_token = c.at;
  bool has_dimension = false;
  if (c.at < c.end - 1 && c.at[0] == 'S' && c.at[1] == 'T') c.at += 2;
  if (c.at < c.end && *c.at == 'C') ++c.at;
  if (c.at < c.end && *c.at == 'N') ++c.at;
  if (c.at < c.end && *c.at == '4') ++c.at;
  if (c.at < c.end && *c.at == 'n') has_dimension = (++c.at, true);
  if (c.at < c.end - 2 && c.at[0] == 'O' && c.at[1] == 'F' && c.at[2] == 'F') {
    c.at += 3;
    c.next_token();
  } else {
    if (c.at != first_token)  // "4 4 6": the reader takes the 4 for the homogeneous prefix
      return "an OFF file without the 'OFF' keyword whose first count starts with " +
             shown_text(std::string(first_token, c.at)) +
             " (assimp 5.2 reads it as a prefix; add an 'OFF' line)";
    c.next_token();
    if (c.at >= c.end || !is_digit(*c.at)) return {};  // the reader refuses the header
  }
  std::string dimension = "3";
  if (has_dimension) {
    dimension = c.digits();
    c.next_token();
  }
  if (wrapped_value(dimension) > 3) return {};  // the reader refuses more than 3 coordinates
  c.next_token();
  const std::string vertex_digits = c.digits();
  c.next_token();
  const std::string face_digits = c.digits();
  c.next_token();
  c.digits();  // edges
  c.next_token();
  for (const std::string* d : {&vertex_digits, &face_digits})
    if (count_value(*d) > file_bytes)
      return "OFF header counts " + shown_text(*d) + " elements, more than the file's " +
             std::to_string(file_bytes) + " bytes could hold";
  const unsigned long long vertices = count_value(vertex_digits);
  const unsigned long long faces = count_value(face_digits);
  if (wrapped_value(vertex_digits) == 0 || wrapped_value(face_digits) == 0)
    return {};  // the reader refuses it

  // The lines: up to a line end (CR, LF, NUL, FF), then every CR, LF and FF after it; a NUL
  // at a line's start ends the file. The reader copies a line into 4096 bytes and its NUL one
  // past them.
  std::string line;
  auto next_line = [&c, &line]() -> int {  // 1: a line, 0: the end, -1: too long
    if (*c.at == '\0') return 0;
    const char* begin = c.at;
    while (!is_assimp_line_end(*c.at)) ++c.at;
    line.assign(begin, c.at);
    while (is_assimp_line_end(*c.at) && *c.at != '\0') ++c.at;
    return line.size() >= 4096 ? -1 : 1;
  };
  const std::string too_long =
      "an OFF line of 4096 characters or more (assimp 5.2 reads lines into 4096 bytes)";
  for (unsigned long long v = 0; v < vertices; ++v) {
    const int got = next_line();
    if (got < 0) return too_long;
    if (got == 0) return {};  // fewer lines than vertices: faces without vertices follow
  }
  for (unsigned long long f = 0; f < faces; ++f) {
    const int got = next_line();
    if (got < 0) return too_long;
    if (got == 0) return {};
    Cursor face{line.c_str(), line.c_str() + line.size()};
    face.skip_spaces();
    const std::string n_digits = face.digits();
    if (n_digits.empty()) return "a face line without a vertex count";
    const unsigned long long n = count_value(n_digits);
    if (n == 0) return "a face without vertices";
    if (n > 9)
      return "an OFF face of " + shown_text(n_digits) +
             " vertices (assimp 5.2 reads faces of 1 to 9 vertices)";
    for (unsigned long long k = 0; k < n; ++k) {
      face.skip_spaces();
      const std::string index = face.digits();
      if (index.empty() || (*face.at != ' ' && *face.at != '\t' && *face.at != '\0'))
        return "a face line without its " + std::to_string(n) + " vertex indices";
      if (count_value(index) >= vertices) return "a face index past the vertices";
    }
  }
  return {};
}

}  // namespace cordgrasp::detail
