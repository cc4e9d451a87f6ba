#include "cordgrasp/render/renderer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

#include "cordgrasp/core/shapes.h"
#include "cordgrasp/render/text.h"
#include "gl_functions.h"
#include "mesh_arrays.h"
#include "osmesa_context.h"
#include "shaders.h"

namespace cordgrasp {
namespace {

using render_detail::OsMesaContext;
namespace gl = render_detail::gl;

constexpr int kMaxSizePx = 8192;
constexpr int kMaxSupersample = 4;
constexpr int kMaxTargetPx = 16384;  // llvmpipe's largest texture / renderbuffer side
constexpr int kShadowMaskPx = 256;

Eigen::Matrix4f to_float(const Eigen::Matrix4d& m) { return m.cast<float>(); }

GLuint compile_shader(GLenum type, const char* source) {
  const GLuint shader = gl::CreateShader(type);
  gl::ShaderSource(shader, 1, &source, nullptr);
  gl::CompileShader(shader);
  GLint ok = 0;
  gl::GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048] = {0};
    gl::GetShaderInfoLog(shader, sizeof log, nullptr, log);
    gl::DeleteShader(shader);
    throw std::runtime_error(std::string("render: shader compilation failed: ") + log);
  }
  return shader;
}

// A linked GLSL program with cached uniform locations.
class Program {
 public:
  Program() = default;
  Program(const char* vertex, const char* fragment) {
    const GLuint vs = compile_shader(GL_VERTEX_SHADER, vertex);
    const GLuint fs = compile_shader(GL_FRAGMENT_SHADER, fragment);
    id_ = gl::CreateProgram();
    gl::AttachShader(id_, vs);
    gl::AttachShader(id_, fs);
    gl::LinkProgram(id_);
    gl::DeleteShader(vs);
    gl::DeleteShader(fs);
    GLint ok = 0;
    gl::GetProgramiv(id_, GL_LINK_STATUS, &ok);
    if (!ok) {
      char log[2048] = {0};
      gl::GetProgramInfoLog(id_, sizeof log, nullptr, log);
      throw std::runtime_error(std::string("render: shader link failed: ") + log);
    }
  }
  void use() const { gl::UseProgram(id_); }
  GLint loc(const char* name) {
    auto it = locations_.find(name);
    if (it == locations_.end())
      it = locations_.emplace(name, gl::GetUniformLocation(id_, name)).first;
    return it->second;
  }
  void set(const char* name, const Eigen::Matrix4f& m) {
    gl::UniformMatrix4fv(loc(name), 1, GL_FALSE, m.data());
  }
  void set(const char* name, const Eigen::Matrix3f& m) {
    gl::UniformMatrix3fv(loc(name), 1, GL_FALSE, m.data());
  }
  void set(const char* name, const Eigen::Vector4d& v) {
    gl::Uniform4f(loc(name), float(v[0]), float(v[1]), float(v[2]), float(v[3]));
  }
  void set(const char* name, const Eigen::Vector3d& v) {
    gl::Uniform3f(loc(name), float(v[0]), float(v[1]), float(v[2]));
  }
  void set(const char* name, float x, float y) { gl::Uniform2f(loc(name), x, y); }
  void set(const char* name, float x) { gl::Uniform1f(loc(name), x); }
  void set(const char* name, int x) { gl::Uniform1i(loc(name), x); }
  GLuint id() const { return id_; }

 private:
  GLuint id_ = 0;
  std::unordered_map<std::string, GLint> locations_;
};

// Vertex array + buffer of an interleaved (position, normal) triangle list.
struct GpuMesh {
  GLuint vao = 0, vbo = 0;
  GLsizei vertex_count = 0;
  Eigen::Vector3d center_M = Eigen::Vector3d::Zero();  // bounding-box centre, mesh frame
};

GpuMesh upload_mesh(const Mesh& mesh, double crease_angle_rad) {
  const std::vector<float> data = render_detail::smooth_vertex_array(mesh, crease_angle_rad);
  GpuMesh g;
  g.vertex_count = static_cast<GLsizei>(data.size() / 6);
  if (!mesh.vertices.empty()) {
    Eigen::Vector3d lo = mesh.vertices[0], hi = lo;
    for (const auto& v : mesh.vertices) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    g.center_M = 0.5 * (lo + hi);
  }
  gl::GenVertexArrays(1, &g.vao);
  gl::GenBuffers(1, &g.vbo);
  gl::BindVertexArray(g.vao);
  gl::BindBuffer(GL_ARRAY_BUFFER, g.vbo);
  gl::BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(),
                 GL_STATIC_DRAW);
  gl::EnableVertexAttribArray(0);
  gl::VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
  gl::EnableVertexAttribArray(1);
  gl::VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float),
                          reinterpret_cast<void*>(3 * sizeof(float)));
  gl::BindVertexArray(0);
  return g;
}

void free_mesh(GpuMesh& g) {
  if (g.vbo) gl::DeleteBuffers(1, &g.vbo);
  if (g.vao) gl::DeleteVertexArrays(1, &g.vao);
  g = GpuMesh{};
}

// A mesh to draw this frame: GPU buffers, model matrix, look.
struct DrawItem {
  const GpuMesh* gpu = nullptr;
  Eigen::Matrix4d X_WM = Eigen::Matrix4d::Identity();  // may include scaling
  Rgba rgba;
  Shading shading = Shading::kSmooth;
  bool on_top = false;
};

// Thick-line geometry of one width and colour: quads (7 floats per vertex) and caps.
struct LineBatch {
  std::vector<float> quads;  // (pos, other, side) × 6 per segment
  std::vector<float> caps;   // pos per vertex
  double width_px = 1.0;
  Rgba rgba;
  bool on_top = false;
  size_t quad_offset = 0, cap_offset = 0;  // in the frame's shared buffers [floats]
};

void add_segment(LineBatch& b, const Eigen::Vector3d& p, const Eigen::Vector3d& q) {
  const auto vert = [&b](const Eigen::Vector3d& a, const Eigen::Vector3d& o, float side) {
    b.quads.insert(b.quads.end(), {float(a.x()), float(a.y()), float(a.z()), float(o.x()),
                                   float(o.y()), float(o.z()), side});
  };
  // p+ p− q+ / p− q− q+ ; at q the direction is reversed, so its sides are swapped.
  vert(p, q, 1.0f);
  vert(p, q, -1.0f);
  vert(q, p, -1.0f);
  vert(p, q, -1.0f);
  vert(q, p, 1.0f);
  vert(q, p, -1.0f);
}

LineBatch make_line_batch(const ScenePolyline& l) {
  LineBatch b;
  b.width_px = l.width_px;
  b.rgba = l.rgba;
  b.rgba[3] = 1.0;
  b.on_top = l.on_top;
  const size_t n = l.p_W.size();
  for (size_t i = 0; i + 1 < n; ++i) add_segment(b, l.p_W[i], l.p_W[i + 1]);
  if (l.closed && n > 2) add_segment(b, l.p_W[n - 1], l.p_W[0]);
  for (const auto& p : l.p_W)
    b.caps.insert(b.caps.end(), {float(p.x()), float(p.y()), float(p.z())});
  return b;
}

Eigen::Matrix4d pose_scale(const Eigen::Vector3d& origin, const Eigen::Vector3d& z_axis,
                           const Eigen::Vector3d& scale) {
  Eigen::Matrix4d M = Eigen::Matrix4d::Identity();
  const Eigen::Matrix3d R =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), z_axis).toRotationMatrix();
  M.topLeftCorner<3, 3>() = R * scale.asDiagonal();
  M.topRightCorner<3, 1>() = origin;
  return M;
}

// 1, 2 or 5 times a power of ten, close to `x`.
double nice_step(double x) {
  const double p = std::pow(10.0, std::floor(std::log10(x)));
  const double m = x / p;
  return (m < 1.5 ? 1.0 : m < 3.5 ? 2.0 : m < 7.5 ? 5.0 : 10.0) * p;
}

// Three passes of a box blur of radius r (≈ Gaussian), separable, zero outside.
void blur_mask(std::vector<float>& m, int n, int r) {
  if (r <= 0) return;
  std::vector<float> tmp(m.size());
  for (int pass = 0; pass < 3; ++pass) {
    for (int axis = 0; axis < 2; ++axis) {
      for (int line = 0; line < n; ++line) {
        const auto at = [&](int i) -> float& {
          return axis == 0 ? m[static_cast<size_t>(line) * n + i]
                           : m[static_cast<size_t>(i) * n + line];
        };
        double sum = 0.0;
        for (int i = 0; i <= std::min(r, n - 1); ++i) sum += at(i);
        for (int i = 0; i < n; ++i) {
          const size_t out =
              axis == 0 ? static_cast<size_t>(line) * n + i : static_cast<size_t>(i) * n + line;
          tmp[out] = static_cast<float>(sum / (2 * r + 1));
          if (i + r + 1 < n) sum += at(i + r + 1);
          if (i - r >= 0) sum -= at(i - r);
        }
      }
      m.swap(tmp);
    }
  }
}

// Items with non-finite coordinates (e.g. a physics blow-up) cannot be drawn or framed:
// the scene without them, and how many were dropped.
bool finite(const Eigen::Isometry3d& X) { return X.matrix().allFinite(); }

Scene finite_part(const Scene& scene, int& dropped) {
  dropped = 0;
  const auto keep = [&dropped](bool ok) {
    dropped += !ok;
    return ok;
  };
  Scene out = scene;
  out.meshes.clear();
  for (const SceneMesh& m : scene.meshes) {
    bool ok = finite(m.X_WM) && m.rgba.allFinite();
    if (ok && m.mesh)
      for (const auto& v : m.mesh->vertices) ok = ok && v.allFinite();
    if (keep(ok)) out.meshes.push_back(m);
  }
  out.polylines.clear();
  for (const ScenePolyline& l : scene.polylines) {
    bool ok = std::isfinite(l.width_px);
    for (const auto& p : l.p_W) ok = ok && p.allFinite();
    if (keep(ok)) out.polylines.push_back(l);
  }
  out.points.clear();
  for (const ScenePoint& p : scene.points)
    if (keep(p.p_W.allFinite() && std::isfinite(p.radius_m))) out.points.push_back(p);
  out.arrows.clear();
  for (const SceneArrow& a : scene.arrows)
    if (keep(a.p_W.allFinite() && a.direction_W.allFinite() && std::isfinite(a.length_m) &&
             std::isfinite(a.shaft_radius_m)))
      out.arrows.push_back(a);
  out.cones.clear();
  for (const SceneCone& c : scene.cones)
    if (keep(c.apex_W.allFinite() && c.axis_W.allFinite() && std::isfinite(c.height_m) &&
             std::isfinite(c.half_angle_rad)))
      out.cones.push_back(c);
  return out;
}

// Caption band under the 3D view (final resolution).
struct CaptionLayout {
  int lines = 0;
  int size_px = 0;
  int band_px = 0;
};

CaptionLayout caption_layout(const Scene& scene, const RenderParams& params) {
  CaptionLayout c;
  if (scene.caption.empty() || !caption_font_available()) return c;
  c.lines = 1 + static_cast<int>(std::count(scene.caption.begin(), scene.caption.end(), '\n'));
  c.size_px = params.caption_size_px > 0
                  ? static_cast<int>(std::lround(params.caption_size_px))
                  : std::max(11, static_cast<int>(std::lround(params.height_px / 36.0)));
  c.band_px = std::min(params.height_px - 1,
                       static_cast<int>(std::lround((1.45 * c.lines + 0.7) * c.size_px)));
  return c;
}

// The floor under one or more scenes and every point the camera must see.
struct FloorFrame {
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ(), fa, fb;  // floor normal and in-floor axes
  double floor = 0.0, top = 0.0;                          // heights along up [m]
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;                  // footprint along fa, fb [m]
  double footprint = 1e-6;                                // largest extent [m]
  bool has_content = false;
  bool ground = false;
  std::vector<Eigen::Vector3d> extent;  // scene points plus their floor projections
};

FloorFrame floor_frame(const std::vector<const Scene*>& scenes, const RenderParams&) {
  FloorFrame ff;
  const Scene& first = *scenes.front();
  ff.up = first.up_W.norm() > 0.0 ? first.up_W.normalized() : Eigen::Vector3d::UnitZ();
  ff.fa = ff.up.unitOrthogonal();
  ff.fb = ff.up.cross(ff.fa);
  std::optional<double> explicit_floor;
  for (const Scene* scene : scenes) {
    const auto p = scene_extent_points(*scene);
    ff.extent.insert(ff.extent.end(), p.begin(), p.end());
    ff.ground = ff.ground || scene->ground != Ground::kNone;
    if (scene->floor_m)
      explicit_floor =
          explicit_floor ? std::min(*explicit_floor, *scene->floor_m) : *scene->floor_m;
  }
  ff.has_content = !ff.extent.empty();
  if (!ff.has_content) {
    // An empty scene still needs a camera: frame a 10 cm cube at the origin.
    ff.extent = {Eigen::Vector3d::Constant(0.05), Eigen::Vector3d::Constant(-0.05)};
  }
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  ff.x0 = ff.y0 = lo;
  ff.x1 = ff.y1 = hi;
  for (const auto& p : ff.extent) {
    lo = std::min(lo, ff.up.dot(p));
    hi = std::max(hi, ff.up.dot(p));
    ff.x0 = std::min(ff.x0, ff.fa.dot(p));
    ff.x1 = std::max(ff.x1, ff.fa.dot(p));
    ff.y0 = std::min(ff.y0, ff.fb.dot(p));
    ff.y1 = std::max(ff.y1, ff.fb.dot(p));
  }
  ff.floor = explicit_floor ? std::min(*explicit_floor, lo) : lo;
  ff.top = hi;
  ff.footprint = std::max({ff.x1 - ff.x0, ff.y1 - ff.y0, ff.top - ff.floor, 1e-6});
  if (ff.ground && ff.has_content) {
    // The floor under the scene must be in view too: the vertical projection of everything low
    // enough to leave a visible shadow (the shadow fades as exp(−height / (0.35 footprint))).
    const size_t n = ff.extent.size();
    const double max_height = 0.5 * ff.footprint;
    for (size_t i = 0; i < n; ++i) {
      const double height = ff.up.dot(ff.extent[i]) - ff.floor;
      if (height < max_height) ff.extent.push_back(ff.extent[i] - height * ff.up);
    }
  }
  return ff;
}

Camera frame_extent(const FloorFrame& ff, const RenderParams& params, double aspect) {
  ViewSpec spec = params.view;
  spec.up_W = ff.up;
  return frame_points(ff.extent, spec, aspect);
}

}  // namespace

struct Renderer::Impl {
  OsMesaContext context;
  Program mesh_program, line_program, cap_program, shadow_program, ground_program, resolve_program;
  GpuMesh unit_sphere, unit_cylinder, unit_arrow_head, unit_cone;
  GLuint line_vao = 0, line_vbo = 0, cap_vao = 0, cap_vbo = 0;
  GLuint ground_vao = 0, ground_vbo = 0, empty_vao = 0;
  GLuint fbo = 0, fbo_color = 0, fbo_depth = 0;
  int fbo_w = 0, fbo_h = 0;
  GLuint shadow_fbo = 0, shadow_color = 0, shadow_depth = 0, shadow_mask = 0;

  struct CachedMesh {
    std::weak_ptr<const Mesh> mesh;
    GpuMesh gpu;
    size_t vertices = 0, triangles = 0;
    double crease = 0.0;
  };
  std::unordered_map<const Mesh*, CachedMesh> cache;

  Impl() {
    context.make_current(16, 16);
    mesh_program = Program(render_detail::kMeshVertex, render_detail::kMeshFragment);
    line_program = Program(render_detail::kLineVertex, render_detail::kFlatFragment);
    cap_program = Program(render_detail::kCapVertex, render_detail::kCapFragment);
    shadow_program = Program(render_detail::kShadowVertex, render_detail::kShadowFragment);
    ground_program = Program(render_detail::kGroundVertex, render_detail::kGroundFragment);
    resolve_program = Program(render_detail::kResolveVertex, render_detail::kResolveFragment);
    constexpr double kPrimitiveCrease = 0.7;
    unit_sphere = upload_mesh(make_sphere_mesh(1.0, 16, 32), kPrimitiveCrease);
    Mesh cylinder;
    append_mesh(cylinder, make_cylinder_mesh(1.0, 1.0, 24),
                Eigen::Isometry3d(Eigen::Translation3d(0.0, 0.0, 0.5)));
    unit_cylinder = upload_mesh(cylinder, kPrimitiveCrease);
    unit_arrow_head = upload_mesh(render_detail::make_unit_cone_mesh(true, 32), kPrimitiveCrease);
    unit_cone = upload_mesh(render_detail::make_unit_cone_mesh(false, 48), kPrimitiveCrease);

    gl::GenVertexArrays(1, &line_vao);
    gl::GenBuffers(1, &line_vbo);
    gl::BindVertexArray(line_vao);
    gl::BindBuffer(GL_ARRAY_BUFFER, line_vbo);
    for (int a = 0; a < 3; ++a) gl::EnableVertexAttribArray(a);
    gl::BindVertexArray(0);
    gl::GenVertexArrays(1, &cap_vao);
    gl::GenBuffers(1, &cap_vbo);
    gl::BindVertexArray(cap_vao);
    gl::BindBuffer(GL_ARRAY_BUFFER, cap_vbo);
    gl::EnableVertexAttribArray(0);
    gl::BindVertexArray(0);
    gl::GenVertexArrays(1, &ground_vao);
    gl::GenBuffers(1, &ground_vbo);
    gl::BindVertexArray(ground_vao);
    gl::BindBuffer(GL_ARRAY_BUFFER, ground_vbo);
    gl::EnableVertexAttribArray(0);
    gl::VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 5 * sizeof(float), nullptr);
    gl::EnableVertexAttribArray(1);
    gl::VertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 5 * sizeof(float),
                            reinterpret_cast<void*>(3 * sizeof(float)));
    gl::BindVertexArray(0);
    gl::GenVertexArrays(1, &empty_vao);

    // Shadow mask target (fixed size) and the blurred mask texture.
    gl::GenFramebuffers(1, &shadow_fbo);
    gl::GenRenderbuffers(1, &shadow_color);
    gl::GenRenderbuffers(1, &shadow_depth);
    gl::BindRenderbuffer(GL_RENDERBUFFER, shadow_color);
    gl::RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, kShadowMaskPx, kShadowMaskPx);
    gl::BindRenderbuffer(GL_RENDERBUFFER, shadow_depth);
    gl::RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, kShadowMaskPx, kShadowMaskPx);
    gl::BindFramebuffer(GL_FRAMEBUFFER, shadow_fbo);
    gl::FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                shadow_color);
    gl::FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, shadow_depth);
    check_framebuffer("shadow mask");
    gl::BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl::GenTextures(1, &shadow_mask);
    gl::BindTexture(GL_TEXTURE_2D, shadow_mask);
    gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    check_gl("initialisation");
  }

  ~Impl() {
    // Another Renderer's context may be current on this thread: delete our objects in ours.
    try {
      context.make_current();
    } catch (...) {
      return;  // nothing to free safely; destroying the context frees everything anyway
    }
    for (auto& [key, c] : cache) free_mesh(c.gpu);
    for (GpuMesh* g : {&unit_sphere, &unit_cylinder, &unit_arrow_head, &unit_cone}) free_mesh(*g);
    const GLuint buffers[] = {line_vbo, cap_vbo, ground_vbo};
    gl::DeleteBuffers(3, buffers);
    const GLuint arrays[] = {line_vao, cap_vao, ground_vao, empty_vao};
    gl::DeleteVertexArrays(4, arrays);
    for (GLuint p : {mesh_program.id(), line_program.id(), cap_program.id(), shadow_program.id(),
                     ground_program.id(), resolve_program.id()})
      gl::DeleteProgram(p);
    release_target();
    gl::DeleteFramebuffers(1, &shadow_fbo);
    const GLuint rbs[] = {shadow_color, shadow_depth};
    gl::DeleteRenderbuffers(2, rbs);
    gl::DeleteTextures(1, &shadow_mask);
  }

  static void check_gl(const char* where) {
    const GLenum e = gl::GetError();
    if (e != GL_NO_ERROR) {
      std::ostringstream s;
      s << "render: OpenGL error 0x" << std::hex << e << " during " << where;
      throw std::runtime_error(s.str());
    }
  }

  static void check_framebuffer(const char* what) {
    const GLenum status = gl::CheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
      std::ostringstream s;
      s << "render: " << what << " framebuffer incomplete (0x" << std::hex << status << ")";
      throw std::runtime_error(s.str());
    }
  }

  void release_target() {
    if (fbo) gl::DeleteFramebuffers(1, &fbo);
    if (fbo_color) gl::DeleteTextures(1, &fbo_color);
    if (fbo_depth) gl::DeleteRenderbuffers(1, &fbo_depth);
    fbo = fbo_color = fbo_depth = 0;
    fbo_w = fbo_h = 0;
  }

  void ensure_target(int w, int h) {
    if (fbo && fbo_w == w && fbo_h == h) return;
    release_target();
    gl::GenFramebuffers(1, &fbo);
    gl::GenTextures(1, &fbo_color);
    gl::BindTexture(GL_TEXTURE_2D, fbo_color);
    gl::TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl::GenRenderbuffers(1, &fbo_depth);
    gl::BindRenderbuffer(GL_RENDERBUFFER, fbo_depth);
    gl::RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, w, h);
    gl::BindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl::FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, fbo_color, 0);
    gl::FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, fbo_depth);
    check_framebuffer("supersampled");
    fbo_w = w;
    fbo_h = h;
  }

  // GPU buffers of `mesh`, uploaded on first use and kept while the mesh lives.
  const GpuMesh* gpu_mesh(const std::shared_ptr<const Mesh>& mesh, double crease) {
    auto it = cache.find(mesh.get());
    if (it != cache.end()) {
      CachedMesh& c = it->second;
      if (c.mesh.lock() == mesh && c.vertices == mesh->vertices.size() &&
          c.triangles == mesh->triangles.size() && c.crease == crease)
        return &c.gpu;
      free_mesh(c.gpu);
      cache.erase(it);
    }
    CachedMesh c;
    c.mesh = mesh;
    c.gpu = upload_mesh(*mesh, crease);
    c.vertices = mesh->vertices.size();
    c.triangles = mesh->triangles.size();
    c.crease = crease;
    return &cache.emplace(mesh.get(), c).first->second.gpu;
  }

  void evict_expired() {
    for (auto it = cache.begin(); it != cache.end();) {
      if (it->second.mesh.expired()) {
        free_mesh(it->second.gpu);
        it = cache.erase(it);
      } else {
        ++it;
      }
    }
  }

  Image render(const Scene& scene, const RenderParams& params, RenderInfo* info);
};

namespace {

// Per-frame state shared by the drawing helpers.
struct Frame {
  Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
  Eigen::Matrix4d proj = Eigen::Matrix4d::Identity();
  Camera camera;
  int w_px = 0, h_px = 0;  // supersampled viewport
  int factor = 1;
  Eigen::Vector3d up_view = Eigen::Vector3d::UnitZ();
};

}  // namespace

Image Renderer::Impl::render(const Scene& input, const RenderParams& params, RenderInfo* info) {
  int dropped = 0;
  const Scene scene = finite_part(input, dropped);
  if (params.width_px < 1 || params.width_px > kMaxSizePx || params.height_px < 1 ||
      params.height_px > kMaxSizePx)
    throw std::invalid_argument("render: image size " + std::to_string(params.width_px) + "x" +
                                std::to_string(params.height_px) + " outside [1, 8192]");
  if (params.supersample < 1 || params.supersample > kMaxSupersample)
    throw std::invalid_argument("render: supersample " + std::to_string(params.supersample) +
                                " outside [1, 4]");

  const int W = params.width_px;
  const CaptionLayout caption = caption_layout(scene, params);
  const int H = params.height_px - caption.band_px;
  const int s = std::max(1, std::min({params.supersample, kMaxTargetPx / W, kMaxTargetPx / H}));

  context.make_current(W, H);
  evict_expired();

  // Camera: explicit or framed on everything drawn (plus the floor under it).
  const FloorFrame ff = floor_frame({&scene}, params);
  const Eigen::Vector3d& up = ff.up;
  const Eigen::Vector3d &fa = ff.fa, &fb = ff.fb;
  const double floor = ff.floor, footprint = ff.footprint;
  const double x0 = ff.x0, x1 = ff.x1, y0 = ff.y0, y1 = ff.y1;
  const bool has_content = ff.has_content;
  const auto on_floor = [&](double a, double b) {
    return Eigen::Vector3d(a * fa + b * fb + floor * up);
  };

  Frame fr;
  const double aspect = static_cast<double>(W) / H;
  fr.camera = params.camera ? *params.camera : frame_extent(ff, params, aspect);
  fr.view = view_transform(fr.camera).matrix();
  fr.proj = projection_matrix(fr.camera, aspect);
  fr.w_px = W * s;
  fr.h_px = H * s;
  fr.factor = s;
  fr.up_view = fr.view.topLeftCorner<3, 3>() * up;
  const float px_scale = fr.camera.orthographic
                             ? float(fr.camera.ortho_height_m / fr.h_px)
                             : float(2.0 * std::tan(0.5 * fr.camera.fov_y_rad) / fr.h_px);

  // Collect the meshes of this frame.
  std::vector<DrawItem> items;
  for (const SceneMesh& m : scene.meshes) {
    if (!m.mesh || m.mesh->triangles.empty()) continue;
    DrawItem d;
    d.gpu = gpu_mesh(m.mesh, params.crease_angle_rad);
    d.X_WM = m.X_WM.matrix();
    d.rgba = m.rgba;
    d.shading = m.shading;
    d.on_top = m.on_top;
    items.push_back(d);
  }
  for (const ScenePoint& p : scene.points) {
    DrawItem d;
    d.gpu = &unit_sphere;
    d.X_WM = pose_scale(p.p_W, Eigen::Vector3d::UnitZ(), Eigen::Vector3d::Constant(p.radius_m));
    d.rgba = p.rgba;
    d.on_top = p.on_top;
    items.push_back(d);
  }
  for (const SceneArrow& a : scene.arrows) {
    if (a.direction_W.norm() == 0.0 || a.length_m <= 0.0) continue;
    const Eigen::Vector3d dir = a.direction_W.normalized();
    const double head = std::min(0.35 * a.length_m, 6.0 * a.shaft_radius_m);
    const double head_r = 2.4 * a.shaft_radius_m;
    DrawItem shaft;
    shaft.gpu = &unit_cylinder;
    shaft.X_WM = pose_scale(a.p_W, dir,
                            Eigen::Vector3d(a.shaft_radius_m, a.shaft_radius_m, a.length_m - head));
    shaft.rgba = a.rgba;
    shaft.on_top = a.on_top;
    items.push_back(shaft);
    DrawItem tip = shaft;
    tip.gpu = &unit_arrow_head;
    tip.X_WM =
        pose_scale(a.p_W + (a.length_m - head) * dir, dir, Eigen::Vector3d(head_r, head_r, head));
    items.push_back(tip);
  }
  for (const SceneCone& c : scene.cones) {
    if (c.axis_W.norm() == 0.0 || c.height_m <= 0.0) continue;
    const double r = c.height_m * std::tan(c.half_angle_rad);
    DrawItem d;
    d.gpu = &unit_cone;
    d.X_WM = pose_scale(c.apex_W, c.axis_W.normalized(), Eigen::Vector3d(r, r, c.height_m));
    d.rgba = c.rgba;
    d.on_top = c.on_top;
    items.push_back(d);
  }

  // Lines of this frame (grid first), uploaded together.
  std::vector<LineBatch> lines;
  const bool camera_above_floor = fr.camera.orthographic
                                      ? (fr.camera.target_W - fr.camera.eye_W).dot(up) < 0.0
                                      : up.dot(fr.camera.eye_W) > floor;
  if (scene.ground == Ground::kGrid && has_content && camera_above_floor) {
    LineBatch grid;
    grid.width_px = 1.0;
    grid.rgba = Rgba(0.80, 0.80, 0.80, 1.0);
    const double step = nice_step(footprint / 6.0);
    const double pad = 0.5 * footprint;
    const double a0 = std::floor((x0 - pad) / step) * step,
                 a1 = std::ceil((x1 + pad) / step) * step;
    const double b0 = std::floor((y0 - pad) / step) * step,
                 b1 = std::ceil((y1 + pad) / step) * step;
    for (double a = a0; a <= a1 + 1e-9 * step; a += step)
      add_segment(grid, on_floor(a, b0), on_floor(a, b1));
    for (double b = b0; b <= b1 + 1e-9 * step; b += step)
      add_segment(grid, on_floor(a0, b), on_floor(a1, b));
    lines.push_back(std::move(grid));
  }
  for (const ScenePolyline& l : scene.polylines)
    if (l.p_W.size() >= 2) lines.push_back(make_line_batch(l));
  {
    std::vector<float> quads, caps;
    for (LineBatch& b : lines) {
      b.quad_offset = quads.size();
      b.cap_offset = caps.size();
      quads.insert(quads.end(), b.quads.begin(), b.quads.end());
      caps.insert(caps.end(), b.caps.begin(), b.caps.end());
    }
    gl::BindVertexArray(line_vao);
    gl::BindBuffer(GL_ARRAY_BUFFER, line_vbo);
    gl::BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(quads.size() * sizeof(float)),
                   quads.data(), GL_STREAM_DRAW);
    gl::VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 7 * sizeof(float), nullptr);
    gl::VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 7 * sizeof(float),
                            reinterpret_cast<void*>(3 * sizeof(float)));
    gl::VertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, 7 * sizeof(float),
                            reinterpret_cast<void*>(6 * sizeof(float)));
    gl::BindVertexArray(cap_vao);
    gl::BindBuffer(GL_ARRAY_BUFFER, cap_vbo);
    gl::BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(caps.size() * sizeof(float)),
                   caps.data(), GL_STREAM_DRAW);
    gl::VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
    gl::BindVertexArray(0);
  }

  // Soft shadow: mask seen from below, blurred on the CPU, laid on the floor quad.
  const bool draw_shadow = scene.ground == Ground::kShadow && has_content && camera_above_floor;
  double sh_a0 = 0, sh_a1 = 0, sh_b0 = 0, sh_b1 = 0;
  if (draw_shadow) {
    const double half = 0.5 * std::max(x1 - x0, y1 - y0) + 0.35 * footprint;
    const double ca = 0.5 * (x0 + x1), cb = 0.5 * (y0 + y1);
    sh_a0 = ca - half;
    sh_a1 = ca + half;
    sh_b0 = cb - half;
    sh_b1 = cb + half;
    // Orthographic camera below the floor looking up; image x = fa, image y = fb.
    Eigen::Matrix4d V = Eigen::Matrix4d::Identity();
    // View space x = fa, y = fb (a mirror image, harmless here: no culling, orthographic, and
    // mask row 0 then lies at b0 like the floor quad's v = 0), z = −up.
    V.block<1, 3>(0, 0) = fa.transpose();
    V.block<1, 3>(1, 0) = fb.transpose();
    V.block<1, 3>(2, 0) = -up.transpose();
    V(0, 3) = -ca;
    V(1, 3) = -cb;
    V(2, 3) = floor - footprint;  // eye a footprint below the floor
    Camera sc;
    sc.orthographic = true;
    sc.ortho_height_m = 2.0 * half;
    sc.near_m = 0.0;
    sc.far_m = 4.0 * footprint;
    const Eigen::Matrix4d VP = projection_matrix(sc, 1.0) * V;
    gl::BindFramebuffer(GL_FRAMEBUFFER, shadow_fbo);
    gl::Viewport(0, 0, kShadowMaskPx, kShadowMaskPx);
    gl::ClearColor(0.f, 0.f, 0.f, 1.f);
    gl::ClearDepth(1.0);
    gl::Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl::Enable(GL_DEPTH_TEST);
    gl::DepthFunc(GL_LESS);
    gl::DepthMask(GL_TRUE);
    gl::Disable(GL_BLEND);
    gl::Disable(GL_CULL_FACE);
    shadow_program.use();
    shadow_program.set("u_view_proj", to_float(VP));
    shadow_program.set("u_up", up);
    shadow_program.set("u_floor", float(floor));
    shadow_program.set("u_falloff", float(0.35 * footprint));
    for (const DrawItem& d : items) {
      if (d.rgba[3] < 0.5 || d.on_top) continue;
      shadow_program.set("u_model", to_float(d.X_WM));
      gl::BindVertexArray(d.gpu->vao);
      gl::DrawArrays(GL_TRIANGLES, 0, d.gpu->vertex_count);
    }
    std::vector<std::uint8_t> raw(kShadowMaskPx * kShadowMaskPx * 4);
    gl::ReadPixels(0, 0, kShadowMaskPx, kShadowMaskPx, GL_RGBA, GL_UNSIGNED_BYTE, raw.data());
    std::vector<float> mask(kShadowMaskPx * kShadowMaskPx);
    for (size_t i = 0; i < mask.size(); ++i) mask[i] = raw[4 * i] / 255.0f;
    blur_mask(mask, kShadowMaskPx, std::max(1, static_cast<int>(kShadowMaskPx * 0.022)));
    std::vector<std::uint8_t> mask8(mask.size());
    for (size_t i = 0; i < mask.size(); ++i) mask8[i] = to_byte(mask[i]);
    gl::BindTexture(GL_TEXTURE_2D, shadow_mask);
    gl::PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl::TexImage2D(GL_TEXTURE_2D, 0, GL_R8, kShadowMaskPx, kShadowMaskPx, 0, GL_RED,
                   GL_UNSIGNED_BYTE, mask8.data());
    // Floor quad: uv (0,0) at (a0, b0).
    const Eigen::Vector3d q[4] = {on_floor(sh_a0, sh_b0), on_floor(sh_a1, sh_b0),
                                  on_floor(sh_a1, sh_b1), on_floor(sh_a0, sh_b1)};
    const float uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    std::vector<float> quad;
    for (int i : {0, 1, 2, 0, 2, 3})
      quad.insert(quad.end(),
                  {float(q[i].x()), float(q[i].y()), float(q[i].z()), uv[i][0], uv[i][1]});
    gl::BindBuffer(GL_ARRAY_BUFFER, ground_vbo);
    gl::BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(quad.size() * sizeof(float)),
                   quad.data(), GL_STREAM_DRAW);
  }

  // Main pass into the supersampled target.
  ensure_target(fr.w_px, fr.h_px);
  gl::BindFramebuffer(GL_FRAMEBUFFER, fbo);
  gl::Viewport(0, 0, fr.w_px, fr.h_px);
  gl::ClearColor(float(params.background[0]), float(params.background[1]),
                 float(params.background[2]), 1.f);
  gl::ClearDepth(1.0);
  gl::Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  gl::Enable(GL_DEPTH_TEST);
  gl::DepthFunc(GL_LEQUAL);
  gl::Disable(GL_CULL_FACE);
  gl::Enable(GL_PROGRAM_POINT_SIZE);

  // Opaque meshes near to far (hidden fragments then fail the depth test before shading),
  // translucent ones far to near (better blending). Stable: ties keep scene order.
  {
    std::vector<double> depth(items.size());
    for (size_t i = 0; i < items.size(); ++i)
      depth[i] = -(fr.view * items[i].X_WM * items[i].gpu->center_M.homogeneous()).z();
    std::vector<size_t> order(items.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
      const bool ta = items[a].rgba[3] < 1.0, tb = items[b].rgba[3] < 1.0;
      if (ta != tb) return !ta;
      return ta ? depth[a] > depth[b] : depth[a] < depth[b];
    });
    std::vector<DrawItem> sorted;
    sorted.reserve(items.size());
    for (size_t i : order) sorted.push_back(items[i]);
    items.swap(sorted);
  }
  const Eigen::Matrix4f view_f = to_float(fr.view), proj_f = to_float(fr.proj);
  const auto draw_meshes = [&](bool on_top, bool translucent) {
    mesh_program.use();
    mesh_program.set("u_proj", proj_f);
    mesh_program.set("u_ortho", int(fr.camera.orthographic));
    mesh_program.set("u_up_view", fr.up_view);
    for (const DrawItem& d : items) {
      if (d.on_top != on_top || (d.rgba[3] < 1.0) != translucent) continue;
      const Eigen::Matrix4d MV = fr.view * d.X_WM;
      const Eigen::Matrix3d N = MV.topLeftCorner<3, 3>().inverse().transpose();
      mesh_program.set("u_model_view", to_float(MV));
      mesh_program.set("u_normal_matrix", Eigen::Matrix3f(N.cast<float>()));
      mesh_program.set("u_color", d.rgba);
      mesh_program.set("u_shading", static_cast<int>(d.shading));
      gl::BindVertexArray(d.gpu->vao);
      gl::DrawArrays(GL_TRIANGLES, 0, d.gpu->vertex_count);
    }
  };
  const auto draw_lines = [&](bool on_top) {
    for (const LineBatch& b : lines) {
      if (b.on_top != on_top) continue;
      const float half = float(0.5 * b.width_px * fr.factor);
      line_program.use();
      line_program.set("u_view", view_f);
      line_program.set("u_proj", proj_f);
      line_program.set("u_viewport", float(fr.w_px), float(fr.h_px));
      line_program.set("u_half_width", half);
      line_program.set("u_px_scale", px_scale);
      line_program.set("u_ortho", int(fr.camera.orthographic));
      line_program.set("u_color", b.rgba);
      gl::BindVertexArray(line_vao);
      gl::DrawArrays(GL_TRIANGLES, static_cast<GLint>(b.quad_offset / 7),
                     static_cast<GLsizei>(b.quads.size() / 7));
      cap_program.use();
      cap_program.set("u_view", view_f);
      cap_program.set("u_proj", proj_f);
      cap_program.set("u_half_width", half);
      cap_program.set("u_px_scale", px_scale);
      cap_program.set("u_ortho", int(fr.camera.orthographic));
      cap_program.set("u_color", b.rgba);
      gl::BindVertexArray(cap_vao);
      gl::DrawArrays(GL_POINTS, static_cast<GLint>(b.cap_offset / 3),
                     static_cast<GLsizei>(b.caps.size() / 3));
    }
  };
  // Floor shadow after the opaque meshes: hidden pixels fail the depth test early.
  const auto draw_ground = [&]() {
    if (!draw_shadow) return;
    gl::Enable(GL_BLEND);
    gl::BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl::DepthMask(GL_FALSE);
    ground_program.use();
    ground_program.set("u_view_proj", to_float(fr.proj * fr.view));
    ground_program.set("u_strength", float(std::clamp(params.shadow_strength, 0.0, 1.0)));
    ground_program.set("u_mask", 0);
    gl::ActiveTexture(GL_TEXTURE0);
    gl::BindTexture(GL_TEXTURE_2D, shadow_mask);
    gl::BindVertexArray(ground_vao);
    gl::DrawArrays(GL_TRIANGLES, 0, 6);
    gl::DepthMask(GL_TRUE);
    gl::Disable(GL_BLEND);
  };
  const auto draw_translucent = [&](bool on_top) {
    gl::Enable(GL_BLEND);
    gl::BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl::DepthMask(GL_FALSE);
    gl::Enable(GL_CULL_FACE);
    for (GLenum cull : {GL_FRONT, GL_BACK}) {  // far side first, then near side
      gl::CullFace(cull);
      draw_meshes(on_top, true);
    }
    gl::Disable(GL_CULL_FACE);
    gl::DepthMask(GL_TRUE);
    gl::Disable(GL_BLEND);
  };
  for (bool on_top : {false, true}) {
    if (on_top) gl::Clear(GL_DEPTH_BUFFER_BIT);
    draw_meshes(on_top, false);
    draw_lines(on_top);
    if (!on_top) draw_ground();
    draw_translucent(on_top);
  }

  // Resolve into the OSMesa framebuffer at output resolution (a plain copy without
  // supersampling).
  if (fr.factor == 1) {
    gl::BindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    gl::BindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    gl::BlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    gl::BindFramebuffer(GL_FRAMEBUFFER, 0);
  } else {
    gl::BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl::Viewport(0, 0, W, H);
    gl::Disable(GL_DEPTH_TEST);
    resolve_program.use();
    resolve_program.set("u_image", 0);
    resolve_program.set("u_factor", fr.factor);
    gl::ActiveTexture(GL_TEXTURE0);
    gl::BindTexture(GL_TEXTURE_2D, fbo_color);
    gl::BindVertexArray(empty_vao);
    gl::DrawArrays(GL_TRIANGLES, 0, 3);
    gl::BindVertexArray(0);
  }
  gl::Finish();
  check_gl("rendering");

  Image image = make_image(W, params.height_px, params.background);
  const std::vector<std::uint8_t>& buf = context.color_buffer();
  for (int y = 0; y < H; ++y) {
    const std::uint8_t* src = buf.data() + static_cast<size_t>(H - 1 - y) * W * 4;
    std::copy(src, src + static_cast<size_t>(W) * 4, image.pixel(0, y));
  }
  for (size_t i = 3; i < static_cast<size_t>(W) * H * 4; i += 4) image.rgba[i] = 255;
  bool caption_drawn = false;
  if (caption.band_px > 0) {
    std::vector<std::string> rows;
    std::istringstream in(scene.caption);
    for (std::string row; std::getline(in, row);) rows.push_back(row);
    const int row_h = caption.band_px / std::max<int>(1, rows.size());
    for (size_t i = 0; i < rows.size(); ++i)
      caption_drawn |= draw_text_centered(image, rows[i], 0, H + static_cast<int>(i) * row_h, W,
                                          row_h, caption.size_px);
  }
  if (info) {
    info->camera = fr.camera;
    info->view_width_px = W;
    info->view_height_px = H;
    info->caption_drawn = caption_drawn;
    info->dropped_items = dropped;
  }
  return image;
}

Renderer::Renderer() : impl_(std::make_unique<Impl>()) {}
Renderer::~Renderer() = default;

Image Renderer::render(const Scene& scene, const RenderParams& params, RenderInfo* info) {
  return impl_->render(scene, params, info);
}

std::string Renderer::gl_description() const { return impl_->context.description(); }

Camera frame_scenes(const std::vector<Scene>& scenes, const RenderParams& params) {
  if (scenes.empty()) throw std::invalid_argument("frame_scenes: no scenes");
  std::vector<const Scene*> ptrs;
  for (const Scene& s : scenes) ptrs.push_back(&s);
  const int h = params.height_px - caption_layout(scenes.front(), params).band_px;
  return frame_extent(floor_frame(ptrs, params), params, static_cast<double>(params.width_px) / h);
}

Image render_scene(const Scene& scene, const RenderParams& params) {
  Renderer renderer;
  return renderer.render(scene, params);
}

}  // namespace cordgrasp
