#pragma once
// Paths and helpers shared by the test executables.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace cordgrasp::test {

/// The repository root.
inline std::string source_dir() { return CORDGRASP_SOURCE_DIR; }

/// Small hand-written input files under tests/data.
inline std::string test_data(const std::string& rel) {
  return std::string(CORDGRASP_TEST_DATA_DIR) + "/" + rel;
}

/// ../shared/data (third-party hands and objects); empty string when absent.
inline std::string shared_data_dir() {
  const std::string dir = CORDGRASP_SHARED_DATA_DIR;
  return std::filesystem::is_directory(dir) ? dir : std::string();
}

/// Files with extension `ext` directly in `dir`, sorted.
inline std::vector<std::string> files_in(const std::string& dir, const std::string& ext) {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ext) out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

/// Result of running the cordgrasp executable.
struct CommandResult {
  int exit_code = -1;
  std::string output;  ///< stdout and stderr, interleaved
};

/// Runs `cordgrasp <args>` through the shell, capturing stdout+stderr.
inline CommandResult run_cordgrasp(const std::string& args) {
  CommandResult r;
  const std::string cmd = std::string("\"") + CORDGRASP_EXE + "\" " + args + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf{};
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) r.output.append(buf.data(), n);
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

}  // namespace cordgrasp::test

/// Skips the current test, naming the folder, when ../shared/data is absent.
#define CORDGRASP_REQUIRE_SHARED_DATA()                                                  \
  do {                                                                                  \
    if (::cordgrasp::test::shared_data_dir().empty())                                   \
      GTEST_SKIP() << "shared dataset folder '" CORDGRASP_SHARED_DATA_DIR               \
                      "' is absent: this test needs the third-party hands/objects";     \
  } while (0)
