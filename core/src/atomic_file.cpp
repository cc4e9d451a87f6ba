#include "cordgrasp/core/atomic_file.h"

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>

#include "cordgrasp/core/error.h"

namespace cordgrasp {
namespace {

/// "<path>.<pid>.<n>.tmp": unique per process and call, so that two writers of one file (two
/// processes or threads) never share a temporary file.
std::string temp_path_for(const std::string& path) {
  static std::atomic<unsigned long> counter{0};
  return path + "." + std::to_string(static_cast<long>(::getpid())) + "." +
         std::to_string(counter++) + ".tmp";
}

}  // namespace

void write_file_atomically(const std::string& path, const std::string& bytes) {
  write_file_atomically(path, [&bytes](std::ostream& out) {
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  });
}

void write_file_atomically(const std::string& path,
                           const std::function<void(std::ostream&)>& write) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(path, ec))
    throw InputError("'" + path + "': is a directory, cannot write a file there");
  const std::string tmp = temp_path_for(path);
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw InputError("'" + path + "': cannot open for writing");
    try {
      write(out);
    } catch (...) {
      out.close();
      fs::remove(tmp, ec);
      throw;
    }
    out.flush();
    if (!out) {
      out.close();
      fs::remove(tmp, ec);
      throw InputError("'" + path + "': write failed");
    }
  }
  fs::rename(tmp, path, ec);
  if (ec) {
    const std::string reason = ec.message();  // before remove() overwrites ec
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw InputError("'" + path + "': cannot move temp file into place: " + reason);
  }
}

}  // namespace cordgrasp
