#pragma once
// Shared by the fuzz targets: each input is written to a file in one temporary folder per
// process (the parsers read paths, not bytes), and bad-input exceptions are swallowed.
#include <cstddef>
#include <cstdint>
#include <string>

namespace cordgrasp::fuzz {

/// The process's temporary folder (created on first use under $TMPDIR or /tmp, removed at exit).
const std::string& fuzz_dir();

/// Copies the shipped hand's URDF `hand_name`.urdf (assets/hands/<hand_name>/) into fuzz_dir(),
/// so that descriptions there can name it by a relative path. @returns its path.
std::string copy_shipped_urdf(const std::string& hand_name);

/// Writes `text` to fuzz_dir()/`name`. @returns its path.
std::string write_fuzz_file(const std::string& name, const std::string& text);

/// A fuzz input as the file fuzz_dir()/`name`, removed when the object goes away.
class FuzzInputFile {
 public:
  FuzzInputFile(const std::string& name, const uint8_t* data, size_t size);
  ~FuzzInputFile();
  FuzzInputFile(const FuzzInputFile&) = delete;
  FuzzInputFile& operator=(const FuzzInputFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

/// Runs `f`; the exceptions a parser throws for bad input (InputError and the other
/// std::exception kinds) end it quietly. Anything else propagates: a finding.
template <typename F>
void expect_input_errors(F&& f) {
  try {
    f();
  } catch (const std::exception&) {
  }
}

}  // namespace cordgrasp::fuzz
