#pragma once
// Numbers as text for human-facing output (help, reports, CSV).
#include <cstdio>
#include <string>

namespace cordgrasp {

/// `value` printed with a printf format for one double, e.g. "%.3g", "%.6f".
inline std::string format_number(double value, const char* format = "%g") {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

/// `value` with `digits` digits after the point ("%.*f").
inline std::string fixed(double value, int digits) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", digits, value);
  return text;
}

}  // namespace cordgrasp
