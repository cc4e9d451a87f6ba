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

/// A plan ran correctly but found no force-closure grasp (the tools exit with kExitNoGrasp).
class NoGraspFound : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A job stopped early on request (SIGINT / SIGTERM, CancelToken) after writing what it had,
/// marked incomplete; the tools exit with kExitInterrupted. The message says what was written.
class Interrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Exit codes of the tools: 1 = error (one line on stderr), 2 = `bench --strict` with error
/// rows, 3 = no force-closure grasp found, 130 = interrupted (SIGINT), 105–120 = CLI11 refusals.
constexpr int kExitError = 1;
constexpr int kExitNoGrasp = 3;
constexpr int kExitInterrupted = 130;

}  // namespace cordgrasp
