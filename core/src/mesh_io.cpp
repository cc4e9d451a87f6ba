#include "cordgrasp/core/mesh_io.h"

#include <assimp/DefaultIOSystem.h>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <future>
#include <iomanip>
#include <iostream>
#include <memory>
#include <mutex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <vector>

#include "cordgrasp/core/atomic_file.h"
#include "cordgrasp/core/enum_names.h"
#include "cordgrasp/core/error.h"
#include "cordgrasp/core/mesh_properties.h"
#include "huge_pages.h"
#include "mesh_cache.h"
#include "mesh_text.h"
#include "obj_check.h"
#include "off_check.h"
#include "ply_check.h"
#include "weld_table.h"

namespace cordgrasp {
namespace fs = std::filesystem;

constexpr EnumName<LengthUnits> kLengthUnitsNames[] = {{LengthUnits::kMeters, "m"},
                                                        {LengthUnits::kMillimeters, "mm"},
                                                        {LengthUnits::kAuto, "auto"}};

const char* to_string(LengthUnits units) { return enum_to_string(units, kLengthUnitsNames); }

LengthUnits parse_length_units(const std::string& text) {
  return parse_enum(text, kLengthUnitsNames, "units");
}

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& problem) {
  throw InputError("load_mesh: '" + path + "': " + problem);
}

/// Appends the triangles of `node` and its children, with node transforms applied (as RViz and
/// ROS do). Vertices are welded on exact coordinates so that C is the mean of distinct points.
/// Triangles with a NaN/inf corner are left out and counted.
struct SoupBuilder {
  detail::WeldTable index_of;
  Mesh mesh;
  int faces_seen = 0;            ///< faces of any kind (points, lines, polygons)
  int non_finite_triangles = 0;  ///< triangles with a NaN/inf corner
  Eigen::Vector3d first_non_finite = Eigen::Vector3d::Zero();

  int add_vertex(const Eigen::Vector3d& v) {
    const int id = int(mesh.vertices.size());
    const int found =
        index_of.find_or_insert(v, id, [this](int i) -> const Eigen::Vector3d& {
          return mesh.vertices[size_t(i)];
        });
    if (found >= 0) return found;
    mesh.vertices.push_back(v);
    return id;
  }

  void add_node(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent) {
    const aiMatrix4x4 X = parent * node.mTransformation;
    for (unsigned m = 0; m < node.mNumMeshes; ++m) {
      const aiMesh& am = *scene.mMeshes[node.mMeshes[m]];
      faces_seen += int(am.mNumFaces);
      // Welded id of each of the mesh's vertices once it is used (a reader that shares vertices
      // between faces, as PLY's does, then welds each vertex once, not once per face corner).
      std::vector<int> welded(am.mNumVertices, -1);
      for (unsigned f = 0; f < am.mNumFaces; ++f) {
        if (f + unsigned(detail::kWeldLookAhead) < am.mNumFaces) {
          const aiFace& ahead = am.mFaces[f + unsigned(detail::kWeldLookAhead)];
          for (unsigned k = 0; k < ahead.mNumIndices && k < 3; ++k)
            if (welded[ahead.mIndices[k]] < 0) {
              const aiVector3D q = X * am.mVertices[ahead.mIndices[k]];
              index_of.prefetch(Eigen::Vector3d(q.x, q.y, q.z));
            }
        }
        const aiFace& face = am.mFaces[f];
        if (face.mNumIndices != 3) continue;  // points and lines are not surface
        Eigen::Vector3d p[3];
        bool finite = true;
        for (int k = 0; k < 3; ++k) {
          const aiVector3D& raw = am.mVertices[face.mIndices[k]];
          const aiVector3D q = X * raw;
          p[k] = Eigen::Vector3d(q.x, q.y, q.z);
          if (finite && !p[k].allFinite()) {
            // Report the file's coordinates (a transform would smear one NaN over x, y, z).
            const Eigen::Vector3d file_p(raw.x, raw.y, raw.z);
            if (non_finite_triangles == 0) first_non_finite = file_p.allFinite() ? p[k] : file_p;
            finite = false;
          }
        }
        if (!finite) {
          ++non_finite_triangles;
          continue;
        }
        int ids[3];
        for (int k = 0; k < 3; ++k) {
          int& id = welded[face.mIndices[k]];
          if (id < 0) id = add_vertex(p[k]);
          ids[k] = id;
        }
        mesh.triangles.emplace_back(ids[0], ids[1], ids[2]);
      }
    }
    for (unsigned c = 0; c < node.mNumChildren; ++c) add_node(scene, *node.mChildren[c], X);
  }
};

/// A triangle whose altitude is below this fraction of the bounding-box diagonal has zero area
/// within the precision of assimp's float coordinates (2^-23 ≈ 1.2e-7).
constexpr double kDegenerateAltitudeRel = 1e-7;

struct RefusedFile {
  std::string file;
  std::string why;
};

/// Assimp's file system confined to the mesh's own folder: a reference to a file elsewhere
/// (an OBJ's `mtllib ../../etc/passwd`, a glTF buffer `../x.bin`) is not opened. Only geometry
/// is read, so a refused material file costs nothing (assimp falls back to no materials); a
/// refused glTF buffer fails the load with assimp's message. A symlink is followed to where
/// it points, and refused if that is elsewhere; so is a side file starting with a UTF-32 mark
/// (mesh_text.h). Each refused file is named once on stderr.
class MeshFolderIOSystem : public Assimp::DefaultIOSystem {
 public:
  explicit MeshFolderIOSystem(const std::string& mesh_path)
      : self_(resolved(mesh_path)), folder_(resolved(fs::absolute(mesh_path).parent_path())) {}

  bool Exists(const char* file) const override {
    return allowed(file) && Assimp::DefaultIOSystem::Exists(file);
  }
  Assimp::IOStream* Open(const char* file, const char* mode) override {
    if (!allowed(file)) return nullptr;
    // A side file (an OBJ's material library) is read as text too (see load_mesh).
    if (resolved(file) != self_ && !detail::file_utf32_mark_problem(file).empty()) {
      refuse(file, "it starts with a UTF-32 byte-order mark, which assimp 5.2 reads past");
      return nullptr;
    }
    return Assimp::DefaultIOSystem::Open(file, mode);
  }
  /// Files asked for and refused, in first-asked order.
  const std::vector<RefusedFile>& refused() const { return refused_; }

 private:
  static fs::path resolved(const fs::path& p) {
    std::error_code ec;
    const fs::path r = fs::weakly_canonical(fs::absolute(p, ec), ec);
    return ec ? fs::path() : r;
  }
  bool allowed(const char* file) const {
    const fs::path p = resolved(file);
    const fs::path rel = folder_.empty() ? fs::path() : p.lexically_relative(folder_);
    if (!p.empty() && (p == self_ || (!rel.empty() && *rel.begin() != "..")))
      return true;
    refuse(file, "outside the mesh's folder");
    return false;
  }
  void refuse(const char* file, const char* why) const {
    for (const RefusedFile& r : refused_)
      if (r.file == file) return;
    refused_.push_back({file, why});
  }
  fs::path self_, folder_;
  mutable std::vector<RefusedFile> refused_;
};

/// "cordgrasp: warning: ..." naming the first refused file (assimp asks for variants of one
/// name), once per mesh file for the whole process.
void warn_refused_files(const std::string& path, const std::vector<RefusedFile>& refused) {
  static std::mutex mutex;
  static std::set<std::string> warned;
  const std::lock_guard<std::mutex> lock(mutex);
  if (refused.empty() || !warned.insert(path).second) return;
  std::cerr << "cordgrasp: warning: load_mesh: '" << path << "': not opening '" << refused[0].file
            << "': " << refused[0].why << " (only geometry is read)\n";
}

std::string point_text(const Eigen::Vector3d& p) {
  std::ostringstream out;
  out << '(' << p.x() << ", " << p.y() << ", " << p.z() << ')';
  return out.str();
}

/// Formats whose geometry is all in the file itself (a DAE or glTF may read other files).
bool geometry_in_one_file(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".obj" || ext == ".stl" || ext == ".ply" || ext == ".off";
}

/// Faces from which assimp's scene is freed on another thread (its faces are one allocation
/// each: freeing a scan's millions of them takes a tenth of a second or more).
constexpr size_t kReleaseSceneAsideFaces = 100000;

/// With `release`, a large scene's freeing may still run in it when this returns (the caller
/// waits for it after its own work, e.g. writing the cache entry); without, before it returns.
Mesh load_mesh_file(const std::string& path, const MeshLoadOptions& options, MeshLoadReport* report,
                    std::future<void>* release = nullptr) {
  std::future<void> own_release;  // declared first: waited for on every way out
  if (!release) release = &own_release;
  std::error_code ec;
  if (!fs::exists(path, ec)) fail(path, "file not found");
  if (fs::is_directory(path, ec)) fail(path, "is a directory, not a mesh file");
  {
    std::ifstream probe(path, std::ios::binary);
    if (!probe) fail(path, "cannot open for reading");
  }
  const uintmax_t file_bytes = fs::file_size(path, ec);
  if (file_bytes == 0 && !ec) fail(path, "empty file (0 bytes)");
  Assimp::Importer importer;
  std::string ext = fs::path(path).extension().string();
  if (ext.empty() || !importer.IsExtensionSupported(ext))
    fail(path, "unknown mesh format '" + ext + "' (use OBJ, STL, PLY, OFF, DAE or glTF)");
  std::string lower_ext = ext;
  for (char& c : lower_ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (const std::string mark = detail::file_utf32_mark_problem(path); !mark.empty())
    fail(path, mark);
  // assimp picks its reader by the extension alone (one reader per extension here): the PLY,
  // OFF and OBJ readers read what the extension names, whatever the file holds.
  const std::string problem = lower_ext == ".ply"   ? detail::ply_problem(path, file_bytes)
                              : lower_ext == ".off" ? detail::off_problem(path, file_bytes)
                              : lower_ext == ".obj" ? detail::obj_problem(path)
                                                    : std::string();
  if (!problem.empty()) fail(path, problem);
  // Collada: keep node transforms and <unit>, drop the up-axis rotation (ROS/RViz semantics).
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  auto* io = new MeshFolderIOSystem(path);
  importer.SetIOHandler(io);  // the importer owns it
  // Read, check the faces, then triangulate: a loader can leave faces without vertices (an OFF
  // file with fewer faces than its header, a malformed PLY) or index past the vertices, and
  // flag polygons in a mesh that holds none; assimp's triangulation asserts (aborting the
  // process) on the first and the last. Each mesh's primitive types are set from its faces.
  // PLY and OFF hold every face's indices in the file itself, a byte or more each: a reader
  // that fills a longer face (ASCII PLY "33030 2 1") would have triangulation take seconds.
  const bool indices_in_file = lower_ext == ".ply" || lower_ext == ".off";
  const aiScene* scene = importer.ReadFile(path, 0);
  if (scene && scene->mRootNode) {
    uintmax_t indices = 0;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
      aiMesh& am = *scene->mMeshes[m];
      unsigned types = 0;
      for (unsigned f = 0; f < am.mNumFaces; ++f) {
        const aiFace& face = am.mFaces[f];
        indices += face.mNumIndices;
        if (indices_in_file && indices > file_bytes)
          fail(path, "its faces list more vertex indices than the file's " +
                         std::to_string(file_bytes) + " bytes could hold");
        if (face.mNumIndices == 0 || !face.mIndices) fail(path, "a face without vertices");
        for (unsigned k = 0; k < face.mNumIndices; ++k)
          if (face.mIndices[k] >= am.mNumVertices) fail(path, "a face index past the vertices");
        const unsigned n = face.mNumIndices;
        types |= n == 1   ? aiPrimitiveType_POINT
                 : n == 2 ? aiPrimitiveType_LINE
                 : n == 3 ? aiPrimitiveType_TRIANGLE
                          : aiPrimitiveType_POLYGON;
      }
      am.mPrimitiveTypes = types;
    }
    scene = importer.ApplyPostProcessing(aiProcess_Triangulate);
  }
  warn_refused_files(path, io->refused());
  if (!scene || !scene->mRootNode)
    fail(path, std::string("cannot parse: ") + importer.GetErrorString());

  SoupBuilder builder;
  {
    // Room for every face and vertex as read: a large mesh's arrays grow without regrowth
    // copies (storage reserved but never written takes no memory).
    size_t faces = 0, vertices = 0;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
      faces += scene->mMeshes[m]->mNumFaces;
      vertices += scene->mMeshes[m]->mNumVertices;
    }
    detail::reserve_huge(builder.mesh.triangles, faces);
    detail::reserve_huge(builder.mesh.vertices, vertices);
    // A closed surface has about half as many distinct vertices as faces: the weld table
    // starts at that (not at an OBJ's vertex per face corner) and grows only for a soup.
    builder.index_of = detail::WeldTable(std::min(vertices, faces / 2 + 16));
  }
  builder.add_node(*scene, *scene->mRootNode, aiMatrix4x4());
  if (builder.faces_seen >= int(kReleaseSceneAsideFaces)) {
    std::unique_ptr<aiScene> read(importer.GetOrphanedScene());
    scene = nullptr;
    try {
      *release =
          std::async(std::launch::async, [read = std::move(read)]() mutable { read.reset(); });
    } catch (const std::system_error&) {
      // no thread to spare: the scene was freed here, with the task that could not start
    }
  }
  Mesh& mesh = builder.mesh;
  if (builder.non_finite_triangles > 0)
    fail(path, "NaN/inf vertex coordinate " + point_text(builder.first_non_finite) + " in " +
                   std::to_string(builder.non_finite_triangles) + " triangle(s)");
  if (mesh.triangles.empty())
    fail(path, builder.faces_seen == 0 ? std::string("0 triangles (no faces in the file)")
                                       : "0 triangles (its " + std::to_string(builder.faces_seen) +
                                             " faces are all points or lines)");

  MeshLoadReport rep;
  double scale = 1.0;
  if (options.units == LengthUnits::kMillimeters) {
    scale = 1e-3;
  } else if (options.units == LengthUnits::kAuto) {
    if (mesh_bounds(mesh).size().norm() > options.auto_mm_diagonal) {
      scale = 1e-3;
      rep.auto_chose_mm = true;
    }
  }
  scale *= options.scale;
  rep.scale_to_m = scale;
  if (scale != 1.0)
    for (auto& v : mesh.vertices) v *= scale;

  // Drop degenerate triangles: repeated corners, or an altitude (to the longest side) below the
  // precision of the file's float coordinates relative to the mesh size.
  const double min_altitude = kDegenerateAltitudeRel * mesh_bounds(mesh).size().norm();
  auto degenerate = [&](const Eigen::Vector3i& t) {
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return true;
    const Eigen::Vector3d& a = mesh.vertices[t[0]];
    const Eigen::Vector3d& b = mesh.vertices[t[1]];
    const Eigen::Vector3d& c = mesh.vertices[t[2]];
    const double longest =
        std::sqrt(std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()}));
    const double double_area = (b - a).cross(c - a).norm();
    return !(double_area > min_altitude * longest);
  };
  const size_t read = mesh.triangles.size();
  mesh.triangles.erase(std::remove_if(mesh.triangles.begin(), mesh.triangles.end(), degenerate),
                       mesh.triangles.end());
  rep.degenerate_dropped = int(read - mesh.triangles.size());
  if (mesh.triangles.empty())
    fail(path, "all " + std::to_string(read) + " triangles are degenerate (zero area)");

  // Compact: keep only referenced vertices, in first-use order. The weld numbered the vertices
  // in first-use order over the triangles read, so with none dropped that is their order.
  if (rep.degenerate_dropped > 0) {
    std::vector<int> remap;
    detail::assign_huge(remap, mesh.vertices.size(), -1);
    std::vector<Eigen::Vector3d> used;
    detail::reserve_huge(used, mesh.vertices.size());
    for (auto& t : mesh.triangles)
      for (int k = 0; k < 3; ++k) {
        int& r = remap[t[k]];
        if (r < 0) {
          r = int(used.size());
          used.push_back(mesh.vertices[t[k]]);
        }
        t[k] = r;
      }
    mesh.vertices = std::move(used);
  }
  mesh.name = fs::path(path).stem().string();
  if (report) *report = rep;
  return std::move(mesh);  // the builder's, not a copy
}

}  // namespace

Mesh load_mesh(const std::string& path, const MeshLoadOptions& options, MeshLoadReport* report) {
  if (!(std::isfinite(options.scale) && options.scale > 0.0))
    throw std::invalid_argument("load_mesh: scale must be finite and > 0");
  std::error_code ec;
  const uintmax_t file_bytes = fs::file_size(path, ec);
  if (options.cache_folder.empty() || ec || file_bytes < options.cache_min_file_bytes ||
      !geometry_in_one_file(path))
    return load_mesh_file(path, options, report);
  const std::string cached = detail::mesh_cache_file(path, options);
  MeshLoadReport rep;
  if (!cached.empty()) {
    if (std::optional<Mesh> mesh = detail::read_cached_mesh(cached, rep)) {
      mesh->name = fs::path(path).stem().string();
      rep.from_cache = true;
      if (report) *report = rep;
      return std::move(*mesh);
    }
  }
  std::future<void> release;  // the scene freed while the entry is written
  Mesh mesh = load_mesh_file(path, options, &rep, &release);
  if (!cached.empty()) detail::write_cached_mesh(cached, mesh, rep, options.cache_max_bytes);
  if (report) *report = rep;
  return mesh;
}

void save_mesh_obj(const Mesh& mesh, const std::string& path) {
  std::ostringstream out;
  out << "# " << mesh.name << " (cordgrasp, meters)\n" << std::setprecision(9);
  for (const auto& v : mesh.vertices) out << "v " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  for (const auto& t : mesh.triangles)
    out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  write_file_atomically(path, out.str());
}

}  // namespace cordgrasp
