#pragma once
// Private to cordgrasp::render: the OpenGL and OSMesa functions the renderer calls, as pointers
// filled from libOSMesa when the first context is made. Linked instead, libOSMesa (and llvmpipe's
// libLLVM with it) would be loaded and relocated at the start of every program that links the
// renderer, whether it renders or not.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>

// Every GL function the renderer calls, without its "gl" prefix.
#define CORDGRASP_GL_FUNCTIONS(X)                                                                  \
  X(ActiveTexture)                                                                                 \
  X(AttachShader) X(BindBuffer) X(BindFramebuffer) X(BindRenderbuffer) X(BindTexture) X(           \
      BindVertexArray) X(BlendFunc) X(BlitFramebuffer) X(BufferData) X(CheckFramebufferStatus)     \
      X(Clear) X(ClearColor) X(ClearDepth) X(CompileShader) X(CreateProgram) X(CreateShader) X(    \
          CullFace) X(DeleteBuffers) X(DeleteFramebuffers) X(DeleteProgram) X(DeleteRenderbuffers) \
          X(DeleteShader) X(DeleteTextures) X(DeleteVertexArrays) X(DepthFunc) X(DepthMask)        \
              X(Disable) X(DrawArrays) X(Enable) X(EnableVertexAttribArray) X(Finish)              \
                  X(FramebufferRenderbuffer) X(FramebufferTexture2D) X(GenBuffers)                 \
                      X(GenFramebuffers) X(GenRenderbuffers) X(GenTextures) X(GenVertexArrays)     \
                          X(GetError) X(GetProgramInfoLog) X(GetProgramiv) X(GetShaderInfoLog)     \
                              X(GetShaderiv) X(GetString) X(GetUniformLocation) X(LinkProgram)     \
                                  X(PixelStorei) X(ReadPixels) X(RenderbufferStorage)              \
                                      X(ShaderSource) X(TexImage2D) X(TexParameteri) X(Uniform1f)  \
                                          X(Uniform1i) X(Uniform2f) X(Uniform3f) X(Uniform4f)      \
                                              X(UniformMatrix3fv) X(UniformMatrix4fv)              \
                                                  X(UseProgram) X(VertexAttribPointer) X(Viewport)

// Every OSMesa function the renderer calls, without its "OSMesa" prefix.
#define CORDGRASP_OSMESA_FUNCTIONS(X) X(CreateContextAttribs) X(DestroyContext) X(MakeCurrent)

namespace cordgrasp::render_detail {

/// gl::Clear is glClear, and so on; null until load_gl_functions() succeeds.
namespace gl {
#define CORDGRASP_GL_DECLARE(name) extern decltype(&::gl##name) name;
CORDGRASP_GL_FUNCTIONS(CORDGRASP_GL_DECLARE)
#undef CORDGRASP_GL_DECLARE
}  // namespace gl

/// osmesa::MakeCurrent is OSMesaMakeCurrent, and so on; null until load_gl_functions().
namespace osmesa {
#define CORDGRASP_OSMESA_DECLARE(name) extern decltype(&::OSMesa##name) name;
CORDGRASP_OSMESA_FUNCTIONS(CORDGRASP_OSMESA_DECLARE)
#undef CORDGRASP_OSMESA_DECLARE
}  // namespace osmesa

/// Loads libOSMesa and fills gl:: and osmesa:: (once per process, thread-safe; a failure is
/// remembered and thrown again). @throws std::runtime_error naming the library or the missing
/// function.
void load_gl_functions();

}  // namespace cordgrasp::render_detail
