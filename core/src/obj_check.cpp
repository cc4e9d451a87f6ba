#include "obj_check.h"

#include <fstream>
#include <vector>

#include "mesh_text.h"

namespace cordgrasp::detail {

std::string obj_problem(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<char> buffer(1 << 20);
  size_t line = 1;
  bool line_start = true, statement = false, first_token = false;
  int slashes = 0;
  bool continuation = false;  // a '\' seen: with a line end next, the line goes on after the LF
  bool skip_to_line_feed = false;
  while (in) {
    in.read(buffer.data(), std::streamsize(buffer.size()));
    const size_t n = size_t(in.gcount());
    for (size_t k = 0; k < n; ++k) {
      const char c = buffer[k];
      if (c == '\n') ++line;
      if (skip_to_line_feed) {  // a joined line: assimp goes on after the next LF
        skip_to_line_feed = c != '\n';
        continue;
      }
      if (continuation && is_assimp_line_end(c)) {
        continuation = false;
        skip_to_line_feed = c != '\n';
        continue;
      }
      continuation = false;  // the '\' was a character of the line
      if (c == '\\') {
        continuation = true;
        continue;
      }
      if (is_assimp_line_end(c)) {
        line_start = true;
        statement = false;
        continue;
      }
      if (line_start) {
        line_start = false;
        statement = c == 'f' || c == 'l' || c == 'p';
        first_token = true;
        slashes = 0;
        continue;
      }
      if (!statement) continue;
      if (c == ' ' || c == '\t') {
        first_token = false;
        slashes = 0;
      } else if (!first_token) {
        if (c == '/')
          ++slashes;
        else if (c >= '0' && c <= '9' && slashes >= 3)
          return "OBJ line " + std::to_string(line) +
                 ": an index after a third '/' in a face, line or point statement (assimp 5.2 "
                 "then reads past its line buffer)";
      }
    }
  }
  return {};
}

}  // namespace cordgrasp::detail
