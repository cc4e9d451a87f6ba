#pragma once
// Text in HTML and SVG documents (report.html).
#include <string>

namespace cordgrasp {

/// `text` with &, <, > and " replaced by entities: safe in element content and quoted
/// attribute values.
inline std::string html_escaped(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace cordgrasp
