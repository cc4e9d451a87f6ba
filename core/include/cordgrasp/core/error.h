#pragma once
#include <stdexcept>
#include <string>

namespace cordgrasp {

/// Bad user input at an I/O boundary (file missing, unreadable, malformed, wrong units).
/// The message names the file and the problem, e.g. "load_mesh: 'mug.obj': 0 triangles".
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace cordgrasp
