#include "gl_functions.h"

#include <dlfcn.h>

#include <stdexcept>
#include <string>

namespace cordgrasp::render_detail {

namespace gl {
#define CORDGRASP_GL_DEFINE(name) decltype(&::gl##name) name = nullptr;
CORDGRASP_GL_FUNCTIONS(CORDGRASP_GL_DEFINE)
#undef CORDGRASP_GL_DEFINE
}  // namespace gl

namespace osmesa {
#define CORDGRASP_OSMESA_DEFINE(name) decltype(&::OSMesa##name) name = nullptr;
CORDGRASP_OSMESA_FUNCTIONS(CORDGRASP_OSMESA_DEFINE)
#undef CORDGRASP_OSMESA_DEFINE
}  // namespace osmesa

namespace {

/// Loads everything; returns an error message, empty on success.
std::string load_all() {
  const char* library = CORDGRASP_OSMESA_LIBRARY;
  void* handle = dlopen(library, RTLD_NOW | RTLD_LOCAL);  // kept for the process's life
  if (!handle) {
    const char* why = dlerror();
    return std::string("render: cannot load ") + library + " (" + (why ? why : "unknown error") +
           "); rendering needs OSMesa (Debian package libosmesa6)";
  }
  const auto get_proc =
      reinterpret_cast<decltype(&::OSMesaGetProcAddress)>(dlsym(handle, "OSMesaGetProcAddress"));
  // The library exports the GL entry points it implements; an extension it only hands out by
  // name comes from OSMesaGetProcAddress.
  auto find = [&](const std::string& name) -> void* {
    if (void* p = dlsym(handle, name.c_str())) return p;
    return get_proc ? reinterpret_cast<void*>(get_proc(name.c_str())) : nullptr;
  };
  std::string missing;
  auto note_missing = [&](const char* name) {
    missing += (missing.empty() ? "" : ", ") + std::string(name);
  };
#define CORDGRASP_GL_LOAD(name)                                      \
  gl::name = reinterpret_cast<decltype(gl::name)>(find("gl" #name)); \
  if (!gl::name) note_missing("gl" #name);
  CORDGRASP_GL_FUNCTIONS(CORDGRASP_GL_LOAD)
#undef CORDGRASP_GL_LOAD
#define CORDGRASP_OSMESA_LOAD(name)                                              \
  osmesa::name = reinterpret_cast<decltype(osmesa::name)>(find("OSMesa" #name)); \
  if (!osmesa::name) note_missing("OSMesa" #name);
  CORDGRASP_OSMESA_FUNCTIONS(CORDGRASP_OSMESA_LOAD)
#undef CORDGRASP_OSMESA_LOAD
  if (!missing.empty())
    return std::string("render: ") + library + " lacks " + missing +
           " (an OSMesa with OpenGL 3.3 is needed)";
  return {};
}

}  // namespace

void load_gl_functions() {
  static const std::string error = load_all();
  if (!error.empty()) throw std::runtime_error(error);
}

}  // namespace cordgrasp::render_detail
