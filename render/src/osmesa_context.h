#pragma once
// Private to cordgrasp::render: the single place that touches OSMesa.
#include <cstdint>
#include <string>
#include <vector>

namespace cordgrasp::render_detail {

/// RAII OSMesa context (OpenGL core profile ≥ 3.3, RGBA8 + 24-bit depth) with its own
/// default framebuffer in host memory. Not copyable; one per thread.
class OsMesaContext {
 public:
  /// @throws std::runtime_error when OSMesa cannot create a 3.3 core (or, failing that,
  ///         compatibility ≥ 3.3) context.
  OsMesaContext();
  ~OsMesaContext();
  OsMesaContext(const OsMesaContext&) = delete;
  OsMesaContext& operator=(const OsMesaContext&) = delete;

  /// Makes the context current on this thread with a default framebuffer of the given size
  /// (reallocated when the size changes). @throws std::runtime_error on failure.
  void make_current(int width_px, int height_px);

  /// Makes the context current on this thread again with its present framebuffer.
  void make_current() { make_current(width_, height_); }

  /// The default framebuffer, bottom row first, RGBA8 (valid after glFinish).
  const std::vector<std::uint8_t>& color_buffer() const { return buffer_; }

  /// "OpenGL <GL_VERSION>, <GL_RENDERER>" recorded at creation.
  const std::string& description() const { return description_; }

 private:
  void* context_ = nullptr;  // OSMesaContext
  std::vector<std::uint8_t> buffer_;
  int width_ = 0, height_ = 0;
  std::string description_;
};

}  // namespace cordgrasp::render_detail
