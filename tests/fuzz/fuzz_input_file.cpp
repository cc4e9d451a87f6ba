#include "fuzz_input_file.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace cordgrasp::fuzz {
namespace {

struct TempDir {
  std::string path;
  TempDir() {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/cordgrasp-fuzz-XXXXXX";
    if (!mkdtemp(pattern.data())) throw std::runtime_error("fuzz: cannot create " + pattern);
    path = pattern;
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

}  // namespace

const std::string& fuzz_dir() {
  static const TempDir dir;
  return dir.path;
}

std::string copy_shipped_urdf(const std::string& hand_name) {
  const fs::path from =
      fs::path(CORDGRASP_SOURCE_DIR) / "assets/hands" / hand_name / (hand_name + ".urdf");
  const fs::path to = fs::path(fuzz_dir()) / from.filename();
  fs::copy_file(from, to, fs::copy_options::overwrite_existing);
  return to.string();
}

std::string write_fuzz_file(const std::string& name, const std::string& text) {
  const std::string path = fuzz_dir() + "/" + name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  if (!out) throw std::runtime_error("fuzz: cannot write " + path);
  return path;
}

FuzzInputFile::FuzzInputFile(const std::string& name, const uint8_t* data, size_t size)
    : path_(write_fuzz_file(name, std::string(reinterpret_cast<const char*>(data), size))) {}

FuzzInputFile::~FuzzInputFile() {
  std::error_code ec;
  fs::remove(path_, ec);
}

}  // namespace cordgrasp::fuzz
