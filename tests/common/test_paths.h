#pragma once
// Paths and helpers shared by the test executables.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
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

/// How a cordgrasp process ended and what it printed, stdout and stderr apart.
struct ProcessResult {
  bool exited = false;    ///< WIFEXITED: it returned or called exit()
  int exit_code = -1;     ///< WEXITSTATUS when exited
  bool signaled = false;  ///< WIFSIGNALED: a signal ended it (a crash, an abort)
  int signal = 0;         ///< WTERMSIG when signaled
  std::string out, err;
};

/// Runs the cordgrasp executable with `args` (no shell: each string is one argument) in the
/// working directory `cwd`, stdout and stderr going to files in `capture_dir`.
inline ProcessResult run_cordgrasp_argv(const std::vector<std::string>& args,
                                        const std::string& cwd, const std::string& capture_dir) {
  const std::string out_path = capture_dir + "/stdout", err_path = capture_dir + "/stderr";
  std::vector<std::string> argv_text = {CORDGRASP_EXE};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);
  ProcessResult r;
  const pid_t pid = ::fork();
  if (pid == 0) {  // child: only async-signal-safe calls until exec
    const int out = ::open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (out < 0 || err < 0 || ::dup2(out, 1) < 0 || ::dup2(err, 2) < 0 || ::chdir(cwd.c_str()))
      ::_exit(127);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  if (pid < 0) return r;
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  r.exited = WIFEXITED(status);
  r.exit_code = r.exited ? WEXITSTATUS(status) : -1;
  r.signaled = WIFSIGNALED(status);
  r.signal = r.signaled ? WTERMSIG(status) : 0;
  const auto slurp = [](const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  };
  r.out = slurp(out_path);
  r.err = slurp(err_path);
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
