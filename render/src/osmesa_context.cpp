#include "osmesa_context.h"

#include <stdexcept>

#include "gl_functions.h"

namespace cordgrasp::render_detail {
namespace {

OSMesaContext create_context(int profile) {
  const int attribs[] = {OSMESA_FORMAT,
                         OSMESA_RGBA,
                         OSMESA_DEPTH_BITS,
                         24,
                         OSMESA_STENCIL_BITS,
                         0,
                         OSMESA_ACCUM_BITS,
                         0,
                         OSMESA_PROFILE,
                         profile,
                         OSMESA_CONTEXT_MAJOR_VERSION,
                         3,
                         OSMESA_CONTEXT_MINOR_VERSION,
                         3,
                         0};
  return osmesa::CreateContextAttribs(attribs, nullptr);
}

}  // namespace

OsMesaContext::OsMesaContext() {
  load_gl_functions();
  OSMesaContext ctx = create_context(OSMESA_CORE_PROFILE);
  if (!ctx) ctx = create_context(OSMESA_COMPAT_PROFILE);
  if (!ctx)
    throw std::runtime_error(
        "render: OSMesa could not create an OpenGL 3.3 context (is libosmesa6 from Mesa "
        "with the gallium llvmpipe/softpipe driver installed?)");
  context_ = ctx;
  try {
    make_current(16, 16);
  } catch (...) {
    osmesa::DestroyContext(ctx);
    context_ = nullptr;
    throw;
  }
  const auto str = [](GLenum name) {
    const GLubyte* s = gl::GetString(name);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
  };
  description_ = "OpenGL " + str(GL_VERSION) + ", " + str(GL_RENDERER);
}

OsMesaContext::~OsMesaContext() {
  if (context_) osmesa::DestroyContext(static_cast<OSMesaContext>(context_));
}

void OsMesaContext::make_current(int width_px, int height_px) {
  if (width_px != width_ || height_px != height_) {
    buffer_.assign(static_cast<size_t>(width_px) * height_px * 4, 0);
    width_ = width_px;
    height_ = height_px;
  }
  if (!osmesa::MakeCurrent(static_cast<OSMesaContext>(context_), buffer_.data(), GL_UNSIGNED_BYTE,
                           width_px, height_px))
    throw std::runtime_error("render: OSMesaMakeCurrent failed for a " + std::to_string(width_px) +
                             "x" + std::to_string(height_px) + " framebuffer");
}

}  // namespace cordgrasp::render_detail
