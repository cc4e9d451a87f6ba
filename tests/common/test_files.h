#pragma once
// Scratch folders, file reading and PNG probing for tests that run the CLI.
#include <gtest/gtest.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>

namespace cordgrasp::test {

/// A fresh empty folder under the system temp folder, named for the running test and the
/// process (parallel ctest runs do not collide), removed at scope exit.
struct TempDir {
  std::filesystem::path path;
  TempDir() {
    std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    std::replace(name.begin(), name.end(), '/', '_');  // parameterized: "Case/id"
    path = std::filesystem::temp_directory_path() /
           ("cordgrasp_test_" + std::to_string(::getpid()) + "_" + name);
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  /// path / name as a string.
  std::string file(const std::string& name) const { return (path / name).string(); }
  /// Writes `text` to path / name (a settings file, say); returns its path.
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path / name) << text;
    return file(name);
  }
};

/// The file's JSON; throws (the test fails) when it is missing or not JSON.
inline nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

/// The file's text; empty when it is missing.
inline std::string read_text(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// Width and height from a PNG's IHDR chunk (bytes 16..23, big-endian); (0, 0) if not a PNG.
inline std::pair<std::uint32_t, std::uint32_t> png_size(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char h[24] = {0};
  in.read(reinterpret_cast<char*>(h), sizeof h);
  const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (!in || !std::equal(sig, sig + 8, h)) return {0, 0};
  const auto be32 = [&h](int i) {
    return (std::uint32_t(h[i]) << 24) | (std::uint32_t(h[i + 1]) << 16) |
           (std::uint32_t(h[i + 2]) << 8) | std::uint32_t(h[i + 3]);
  };
  return {be32(16), be32(20)};
}

/// "path" in double quotes, for a shell command line.
inline std::string quoted(const std::string& path) { return "\"" + path + "\""; }

}  // namespace cordgrasp::test
