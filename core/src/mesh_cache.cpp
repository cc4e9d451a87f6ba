#include "mesh_cache.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <vector>

#include "cordgrasp/core/atomic_file.h"
#include "cordgrasp/core/fnv1a_hash.h"
#include "cordgrasp/core/version.h"
#include "huge_pages.h"

namespace cordgrasp::detail {
namespace {

namespace fs = std::filesystem;

/// Changes whenever load_mesh's output or this file's layout changes: older entries then miss.
constexpr char kFormat[] = "cordgrasp mesh cache 1";
constexpr char kMagic[8] = {'C', 'G', 'M', 'E', 'S', 'H', '1', '\n'};
constexpr char kExtension[] = ".mesh";
constexpr std::size_t kReadChunkBytes = std::size_t(4) << 20;

static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double) &&
              sizeof(Eigen::Vector3i) == 3 * sizeof(int));  // arrays without padding

struct Header {
  char magic[8];
  std::uint64_t key;
  double scale_to_m;
  std::int32_t degenerate_dropped;
  std::int32_t auto_chose_mm;
  std::uint64_t vertices;
  std::uint64_t triangles;
};

std::uint64_t payload_hash(const Mesh& mesh) {
  Fnv1aHash f;
  f.words(mesh.vertices.data(), mesh.vertices.size() * sizeof(Eigen::Vector3d));
  f.words(mesh.triangles.data(), mesh.triangles.size() * sizeof(Eigen::Vector3i));
  return f.h;
}

/// The key in the file's name ("<16 hex digits>.mesh"), or 0.
std::uint64_t key_of(const std::string& file) {
  const std::string stem = fs::path(file).stem().string();
  if (stem.size() != 16) return 0;
  std::uint64_t key = 0;
  for (char c : stem) {
    const int d = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
    if (d < 0) return 0;
    key = key << 4 | std::uint64_t(d);
  }
  return key;
}

void remove_least_recently_used(const fs::path& folder, std::uintmax_t max_bytes) {
  struct Entry {
    fs::file_time_type used;
    std::uintmax_t bytes;
    fs::path path;
  };
  std::vector<Entry> entries;
  std::uintmax_t total = 0;
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->path().extension() != kExtension) continue;
    std::error_code e1, e2;
    Entry entry{fs::last_write_time(it->path(), e1), fs::file_size(it->path(), e2), it->path()};
    if (e1 || e2) continue;
    total += entry.bytes;
    entries.push_back(std::move(entry));
  }
  if (total <= max_bytes) return;
  std::sort(entries.begin(), entries.end(),
            [](const Entry& a, const Entry& b) { return a.used < b.used; });
  for (const Entry& e : entries) {
    if (total <= max_bytes) break;
    if (fs::remove(e.path, ec)) total -= e.bytes;
  }
}

}  // namespace

std::string mesh_cache_file(const std::string& path, const MeshLoadOptions& options) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  Fnv1aHash f;
  f.bytes(kFormat, sizeof kFormat);
  f.bytes(version(), std::char_traits<char>::length(version()));
  f.value(int(options.units));
  f.value(options.auto_mm_diagonal);
  f.value(options.scale);
  std::vector<char> chunk(kReadChunkBytes);  // a multiple of 8: words() runs on unbroken
  std::uint64_t size = 0;
  while (in) {
    in.read(chunk.data(), std::streamsize(chunk.size()));
    const std::size_t n = std::size_t(in.gcount());
    f.words(chunk.data(), n);
    size += n;
  }
  if (in.bad()) return {};
  f.value(size);
  return (fs::path(options.cache_folder) / (hex64(f.h) + kExtension)).string();
}

std::optional<Mesh> read_cached_mesh(const std::string& file, MeshLoadReport& report) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  Header h{};
  if (!in.read(reinterpret_cast<char*>(&h), sizeof h)) return std::nullopt;
  std::error_code ec;
  const std::uintmax_t bytes = fs::file_size(file, ec);
  const std::uint64_t max_count = bytes / sizeof(Eigen::Vector3i);
  if (ec || !std::equal(kMagic, kMagic + 8, h.magic) || h.key != key_of(file) ||
      h.vertices > max_count || h.triangles > max_count || h.vertices == 0 || h.triangles == 0 ||
      bytes != sizeof h + h.vertices * sizeof(Eigen::Vector3d) +
                   h.triangles * sizeof(Eigen::Vector3i) + sizeof(std::uint64_t))
    return std::nullopt;
  Mesh mesh;
  assign_huge(mesh.vertices, std::size_t(h.vertices), Eigen::Vector3d(0.0, 0.0, 0.0));
  assign_huge(mesh.triangles, std::size_t(h.triangles), Eigen::Vector3i(0, 0, 0));
  std::uint64_t stored_hash = 0;
  in.read(reinterpret_cast<char*>(mesh.vertices.data()),
          std::streamsize(h.vertices * sizeof(Eigen::Vector3d)));
  in.read(reinterpret_cast<char*>(mesh.triangles.data()),
          std::streamsize(h.triangles * sizeof(Eigen::Vector3i)));
  in.read(reinterpret_cast<char*>(&stored_hash), sizeof stored_hash);
  if (!in || stored_hash != payload_hash(mesh)) return std::nullopt;
  const int nv = int(h.vertices);
  for (const Eigen::Vector3i& t : mesh.triangles)
    if (t.minCoeff() < 0 || t.maxCoeff() >= nv) return std::nullopt;
  report.scale_to_m = h.scale_to_m;
  report.degenerate_dropped = h.degenerate_dropped;
  report.auto_chose_mm = h.auto_chose_mm != 0;
  fs::last_write_time(file, fs::file_time_type::clock::now(), ec);  // recently used
  return mesh;
}

void write_cached_mesh(const std::string& file, const Mesh& mesh, const MeshLoadReport& report,
                       std::uintmax_t max_bytes) {
  const fs::path folder = fs::path(file).parent_path();
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec) return;
  Header h{};
  std::copy(kMagic, kMagic + 8, h.magic);
  h.key = key_of(file);
  h.scale_to_m = report.scale_to_m;
  h.degenerate_dropped = report.degenerate_dropped;
  h.auto_chose_mm = report.auto_chose_mm ? 1 : 0;
  h.vertices = mesh.vertices.size();
  h.triangles = mesh.triangles.size();
  const std::uint64_t hash = payload_hash(mesh);
  try {
    write_file_atomically(file, [&](std::ostream& out) {
      out.write(reinterpret_cast<const char*>(&h), sizeof h);
      out.write(reinterpret_cast<const char*>(mesh.vertices.data()),
                std::streamsize(h.vertices * sizeof(Eigen::Vector3d)));
      out.write(reinterpret_cast<const char*>(mesh.triangles.data()),
                std::streamsize(h.triangles * sizeof(Eigen::Vector3i)));
      out.write(reinterpret_cast<const char*>(&hash), sizeof hash);
    });
  } catch (const std::exception&) {
    return;  // a full or read-only disk: the next load reads the file again
  }
  remove_least_recently_used(folder, max_bytes);
}

}  // namespace cordgrasp::detail
