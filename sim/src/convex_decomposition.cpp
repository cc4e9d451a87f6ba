#include "cordgrasp/sim/convex_decomposition.h"

#include <HACD/hacdHACD.h>
#include <LinearMath/btConvexHullComputer.h>
#include <meshoptimizer.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <mutex>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

#include "cordgrasp/core/atomic_file.h"
#include "cordgrasp/core/fnv1a_hash.h"
#include "cordgrasp/core/mesh_properties.h"

namespace cordgrasp {

namespace {

/// HACD normalizes the mesh so that its bounding-box diagonal is 2 × this (HACD::m_scale).
constexpr double kHacdScale = 1000.0;
constexpr char kCacheMagic[8] = {'C', 'G', 'H', 'A', 'C', 'D', '1', '\n'};

/// Welds vertices with identical coordinates and drops zero-area triangles (HACD joins
/// triangles through shared vertex indices).
void weld(const Mesh& mesh, std::vector<Eigen::Vector3d>& points,
          std::vector<Eigen::Vector3i>& triangles) {
  std::map<std::array<double, 3>, int> index;
  std::vector<int> remap(mesh.vertices.size());
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Eigen::Vector3d& v = mesh.vertices[i];
    const std::array<double, 3> key = {v.x(), v.y(), v.z()};
    auto [it, inserted] = index.emplace(key, static_cast<int>(points.size()));
    if (inserted) points.push_back(v);
    remap[i] = it->second;
  }
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const int a = remap[static_cast<size_t>(t[0])];
    const int b = remap[static_cast<size_t>(t[1])];
    const int c = remap[static_cast<size_t>(t[2])];
    if (a == b || b == c || a == c) continue;
    const Eigen::Vector3d& pa = mesh.vertices[static_cast<size_t>(t[0])];
    if ((mesh.vertices[static_cast<size_t>(t[1])] - pa)
            .cross(mesh.vertices[static_cast<size_t>(t[2])] - pa)
            .squaredNorm() <= 0.0)
      continue;
    triangles.emplace_back(a, b, c);
  }
}

std::string params_text(const DecompositionParams& p) {
  std::ostringstream s;
  s.precision(17);
  s << "simplified " << p.concavity << ' ' << p.min_parts << ' ' << p.max_hull_vertices << ' '
    << p.compacity_weight << ' ' << p.volume_weight << ' ' << p.connect_distance << ' '
    << p.add_extra_distance_points << ' ' << p.add_face_points << ' ' << p.max_input_triangles;
  return s.str();
}

std::string cache_key(const Mesh& mesh, const DecompositionParams& params) {
  Fnv1aHash f;
  const std::string text = params_text(params);
  f.bytes(text.data(), text.size());
  return mesh_hash(mesh) + "-" + hex64(f.h);
}

std::string serialize(const ConvexDecomposition& d) {
  std::string out(kCacheMagic, sizeof(kCacheMagic));
  auto put = [&out](const void* p, size_t n) {
    out.append(static_cast<const char*>(p), n);
  };
  const std::uint32_t parts = static_cast<std::uint32_t>(d.parts.size());
  put(&parts, sizeof(parts));
  for (const auto& part : d.parts) {
    const std::uint32_t n = static_cast<std::uint32_t>(part.size());
    put(&n, sizeof(n));
    for (const auto& v : part) put(v.data(), 3 * sizeof(double));
  }
  return out;
}

std::optional<ConvexDecomposition> deserialize(const std::string& bytes) {
  size_t pos = 0;
  auto get = [&](void* p, size_t n) {
    if (pos + n > bytes.size()) return false;
    std::memcpy(p, bytes.data() + pos, n);
    pos += n;
    return true;
  };
  char magic[sizeof(kCacheMagic)];
  if (!get(magic, sizeof(magic)) || std::memcmp(magic, kCacheMagic, sizeof(magic)) != 0)
    return std::nullopt;
  std::uint32_t parts = 0;
  if (!get(&parts, sizeof(parts)) || parts > 1000000) return std::nullopt;
  ConvexDecomposition d;
  d.parts.resize(parts);
  for (auto& part : d.parts) {
    std::uint32_t n = 0;
    if (!get(&n, sizeof(n)) || n > 10000000) return std::nullopt;
    part.resize(n);
    for (auto& v : part)
      if (!get(v.data(), 3 * sizeof(double))) return std::nullopt;
  }
  if (pos != bytes.size()) return std::nullopt;
  return d;
}

/// HACD keeps process-wide state (gCancelRequest): one decomposition at a time.
std::mutex& hacd_mutex() {
  static std::mutex m;
  return m;
}

/// The mesh HACD decomposes: the mesh itself when it has at most `max_triangles` triangles,
/// else meshoptimizer's edge-collapse simplification down to that many (every vertex kept where
/// it was; a thin wall keeps both sides, where a grid clustering had merged a cup's inner and
/// outer wall into one sheet and its parts filled the cup); the sloppy simplifier when edge
/// collapses alone cannot get there.
struct HacdInput {
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector3i> triangles;
};

HacdInput simplified_for_decomposition(const std::vector<Eigen::Vector3d>& points,
                                       const std::vector<Eigen::Vector3i>& triangles,
                                       int max_triangles) {
  HacdInput in;
  if (max_triangles <= 0 || static_cast<int>(triangles.size()) <= max_triangles) {
    in.points = points;
    in.triangles = triangles;
    return in;
  }
  std::vector<float> positions;
  positions.reserve(3 * points.size());
  for (const auto& p : points)
    positions.insert(positions.end(), {static_cast<float>(p.x()), static_cast<float>(p.y()),
                                       static_cast<float>(p.z())});
  std::vector<unsigned int> indices;
  indices.reserve(3 * triangles.size());
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) indices.push_back(static_cast<unsigned int>(t[k]));
  const size_t target = 3 * static_cast<size_t>(max_triangles);
  std::vector<unsigned int> kept(indices.size());
  const float no_error_bound = 1.0f;  // relative to the mesh extent: the count decides
  size_t n = meshopt_simplify(kept.data(), indices.data(), indices.size(), positions.data(),
                              points.size(), 3 * sizeof(float), target, no_error_bound);
  if (n > target)
    n = meshopt_simplifySloppy(kept.data(), indices.data(), indices.size(), positions.data(),
                               points.size(), 3 * sizeof(float), target, no_error_bound);
  // Only the vertices the kept triangles use, renumbered in first use.
  std::vector<int> renumber(points.size(), -1);
  for (size_t i = 0; i + 3 <= n; i += 3) {
    Eigen::Vector3i t;
    for (int k = 0; k < 3; ++k) {
      int& r = renumber[kept[i + static_cast<size_t>(k)]];
      if (r < 0) {
        r = static_cast<int>(in.points.size());
        in.points.push_back(points[kept[i + static_cast<size_t>(k)]]);
      }
      t[k] = r;
    }
    in.triangles.push_back(t);
  }
  return in;
}

}  // namespace

std::vector<Eigen::Vector3d> simplified_convex_hull(const std::vector<Eigen::Vector3d>& points,
                                                    int max_vertices) {
  if (points.size() < 4) return points;
  // Exact hull first (fast), so the incremental hull only looks at hull vertices.
  std::vector<double> coords;
  coords.reserve(points.size() * 3);
  for (const auto& p : points) coords.insert(coords.end(), {p.x(), p.y(), p.z()});
  btConvexHullComputer exact;
  exact.compute(coords.data(), 3 * static_cast<int>(sizeof(double)),
                static_cast<int>(points.size()), 0.0, 0.0);
  std::vector<Eigen::Vector3d> hull;
  for (int i = 0; i < exact.vertices.size(); ++i)
    hull.emplace_back(exact.vertices[i].x(), exact.vertices[i].y(), exact.vertices[i].z());
  return reduced_convex_hull(hull, max_vertices);
}

std::vector<Eigen::Vector3d> reduced_convex_hull(const std::vector<Eigen::Vector3d>& hull,
                                                 int max_vertices) {
  if (static_cast<int>(hull.size()) <= std::max(4, max_vertices) || hull.size() < 4) return hull;
  std::vector<HACD::Vec3<HACD::Real>> in;
  in.reserve(hull.size());
  for (const auto& p : hull) in.emplace_back(p.x(), p.y(), p.z());
  const std::lock_guard<std::mutex> lock(hacd_mutex());
  HACD::ICHull ich;
  ich.AddPoints(in.data(), in.size());
  if (ich.Process(static_cast<unsigned long>(std::max(4, max_vertices))) != HACD::ICHullErrorOK ||
      ich.IsFlat())
    return hull;
  const size_t nv = ich.GetMesh().GetNVertices();
  std::vector<HACD::Vec3<HACD::Real>> out(nv);
  std::vector<HACD::Vec3<long>> tris(std::max<size_t>(ich.GetMesh().GetNTriangles(), 1));
  ich.GetMesh().GetIFS(out.data(), tris.data());
  std::vector<Eigen::Vector3d> result;
  result.reserve(nv);
  for (const auto& p : out) result.emplace_back(p.X(), p.Y(), p.Z());
  return result.size() >= 4 ? result : hull;
}

std::string mesh_hash(const Mesh& mesh) {
  Fnv1aHash f;
  const std::uint64_t nv = mesh.vertices.size();
  const std::uint64_t nt = mesh.triangles.size();
  static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double) &&
                sizeof(Eigen::Vector3i) == 3 * sizeof(int));  // arrays without padding
  f.value(nv);
  f.words(mesh.vertices.data(), nv * sizeof(Eigen::Vector3d));
  f.value(nt);
  f.words(mesh.triangles.data(), nt * sizeof(Eigen::Vector3i));
  return hex64(f.h);
}

ConvexDecomposition convex_decomposition(const Mesh& mesh, const DecompositionParams& params) {
  if (mesh.triangles.empty() || mesh.vertices.empty())
    throw std::invalid_argument("convex_decomposition: mesh '" + mesh.name +
                                "' has no triangles");
  const auto start = std::chrono::steady_clock::now();
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector3i> triangles;
  weld(mesh, points, triangles);
  // HACD's cost grows much faster than linearly: decompose a simplified copy.
  const HacdInput input =
      simplified_for_decomposition(points, triangles, params.max_input_triangles);
  ConvexDecomposition out;
  std::vector<std::vector<Eigen::Vector3d>> parts;
  if (input.triangles.size() >= 2) {
    std::vector<HACD::Vec3<HACD::Real>> hp;
    for (const auto& p : input.points) hp.emplace_back(p.x(), p.y(), p.z());
    std::vector<HACD::Vec3<long>> ht;
    for (const auto& t : input.triangles) ht.emplace_back(t[0], t[1], t[2]);
    const std::lock_guard<std::mutex> lock(hacd_mutex());
    HACD::HACD hacd;
    hacd.SetPoints(hp.data());
    hacd.SetNPoints(hp.size());
    hacd.SetTriangles(ht.data());
    hacd.SetNTriangles(ht.size());
    hacd.SetScaleFactor(kHacdScale);
    hacd.SetCompacityWeight(params.compacity_weight);
    hacd.SetVolumeWeight(params.volume_weight);
    hacd.SetNClusters(static_cast<size_t>(std::max(1, params.min_parts)));
    hacd.SetNVerticesPerCH(static_cast<size_t>(std::max(4, params.max_hull_vertices)));
    // HACD works on the mesh scaled to a bounding-box diagonal of 2·scale.
    hacd.SetConcavity(params.concavity * 2.0 * kHacdScale);
    hacd.SetConnectDist(params.connect_distance < 0.0 ? -1.0
                                                      : params.connect_distance * 2.0 *
                                                            kHacdScale);
    hacd.SetAddExtraDistPoints(params.add_extra_distance_points);
    hacd.SetAddFacesPoints(params.add_face_points);
    hacd.SetAddNeighboursDistPoints(false);
    if (hacd.Compute()) {
      const long* partition = hacd.GetPartition();
      const size_t n_parts = hacd.GetNClusters();
      // The vertices each part's triangles use (the simplified copy's are mesh vertices).
      std::vector<std::vector<char>> used(n_parts, std::vector<char>(input.points.size(), 0));
      for (size_t t = 0; t < input.triangles.size(); ++t) {
        const long p = partition[t];
        if (p < 0 || static_cast<size_t>(p) >= n_parts) continue;
        for (int k = 0; k < 3; ++k)
          used[static_cast<size_t>(p)][static_cast<size_t>(input.triangles[t][k])] = 1;
      }
      for (size_t p = 0; p < n_parts; ++p) {
        std::vector<Eigen::Vector3d> part;
        for (size_t c = 0; c < input.points.size(); ++c)
          if (used[p][c]) part.push_back(input.points[c]);
        if (part.size() >= 4) parts.push_back(std::move(part));
      }
    }
  }
  for (auto& part : parts) {
    auto hull = simplified_convex_hull(part, params.max_hull_vertices);
    if (hull.size() >= 4) out.parts.push_back(std::move(hull));
  }
  if (out.parts.empty())  // HACD failed or the mesh is tiny: the whole mesh's hull
    out.parts.push_back(simplified_convex_hull(points, params.max_hull_vertices));
  out.compute_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

std::shared_ptr<const ConvexDecomposition> cached_convex_decomposition(
    const Mesh& mesh, const DecompositionParams& params, const std::string& cache_dir) {
  static std::mutex mutex;
  static std::unordered_map<std::string, std::shared_ptr<const ConvexDecomposition>> memory;
  const std::string key = cache_key(mesh, params);
  {
    const std::lock_guard<std::mutex> lock(mutex);
    auto it = memory.find(key);
    if (it != memory.end()) {
      auto copy = std::make_shared<ConvexDecomposition>(*it->second);
      copy->from_cache = true;
      copy->compute_s = 0.0;
      return copy;
    }
  }
  std::shared_ptr<ConvexDecomposition> result;
  const std::string path = cache_dir.empty() ? std::string() : cache_dir + "/" + key + ".hacd";
  if (!path.empty()) {
    std::ifstream in(path, std::ios::binary);
    if (in) {
      std::ostringstream bytes;
      bytes << in.rdbuf();
      if (auto d = deserialize(bytes.str())) {
        result = std::make_shared<ConvexDecomposition>(std::move(*d));
        result->from_cache = true;
      }
    }
  }
  if (!result) {
    result = std::make_shared<ConvexDecomposition>(convex_decomposition(mesh, params));
    if (!path.empty()) write_file_atomically(path, serialize(*result));
  }
  const std::lock_guard<std::mutex> lock(mutex);
  memory.emplace(key, result);
  return result;
}

}  // namespace cordgrasp
