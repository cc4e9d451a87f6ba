#include "cordgrasp/core/atomic_file.h"

#include <filesystem>
#include <fstream>

#include "cordgrasp/core/error.h"

namespace cordgrasp {

void write_file_atomically(const std::string& path, const std::string& bytes) {
  namespace fs = std::filesystem;
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw InputError("'" + path + "': cannot open for writing");
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) {
      out.close();
      std::error_code ec;
      fs::remove(tmp, ec);
      throw InputError("'" + path + "': write failed");
    }
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw InputError("'" + path + "': cannot move temp file into place: " + ec.message());
  }
}

}  // namespace cordgrasp
