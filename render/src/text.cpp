#include "cordgrasp/render/text.h"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>

namespace cordgrasp {
namespace {

// FreeType faces for the process, one per font path, loaded on first use; a path that fails
// is warned about once and remembered.
class Font {
 public:
  /// The face for the current caption_font_path(), or null.
  static Font& instance() {
    static std::mutex registry_mutex;
    static std::map<std::string, std::unique_ptr<Font>> fonts;
    const std::string path = caption_font_path();
    std::lock_guard<std::mutex> lock(registry_mutex);
    std::unique_ptr<Font>& font = fonts[path];
    if (!font) font.reset(new Font(path));
    return *font;
  }

  std::mutex& mutex() { return mutex_; }
  FT_Face face() const { return face_; }
  ~Font() {
    if (face_) FT_Done_Face(face_);
    if (library_) FT_Done_FreeType(library_);
  }

 private:
  explicit Font(const std::string& path) {
    if (!std::filesystem::exists(path)) {
      warn("font '" + path + "' not found");
      return;
    }
    if (FT_Init_FreeType(&library_) != 0) {
      library_ = nullptr;
      warn("FreeType initialisation failed");
      return;
    }
    if (FT_New_Face(library_, path.c_str(), 0, &face_) != 0) {
      face_ = nullptr;
      warn("FreeType cannot load font '" + path + "'");
    }
  }
  static void warn(const std::string& what) {
    std::cerr << "cordgrasp: warning: " << what
              << "; pictures are rendered without captions (install fonts-dejavu-core or set "
                 "CORDGRASP_FONT)\n";
  }

  std::mutex mutex_;
  FT_Library library_ = nullptr;
  FT_Face face_ = nullptr;
};

// UTF-8 → code points; invalid bytes become U+FFFD.
std::u32string decode_utf8(const std::string& s) {
  std::u32string out;
  for (size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    int len = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
    if (len == 0 || i + len > s.size()) {
      out.push_back(0xFFFD);
      ++i;
      continue;
    }
    char32_t cp = len == 1 ? c : len == 2 ? (c & 0x1F) : len == 3 ? (c & 0x0F) : (c & 0x07);
    bool ok = true;
    for (int k = 1; k < len; ++k) {
      const auto cc = static_cast<unsigned char>(s[i + k]);
      if ((cc >> 6) != 0x2) ok = false;
      cp = (cp << 6) | (cc & 0x3F);
    }
    out.push_back(ok ? cp : 0xFFFD);
    i += ok ? len : 1;
  }
  return out;
}

constexpr FT_Int32 kLoadFlags = FT_LOAD_TARGET_LIGHT;

// Walks `text` glyph by glyph from pen position `pen` (26.6 units) with kerning: calls
// on_glyph(pen) with each loaded glyph in face->glyph, then advances. Returns the end pen.
// The caller holds the font mutex.
template <class OnGlyph>
long walk_glyphs(FT_Face face, const std::u32string& text, long pen, const OnGlyph& on_glyph) {
  FT_UInt previous = 0;
  for (char32_t cp : text) {
    const FT_UInt glyph = FT_Get_Char_Index(face, cp);
    if (previous && glyph && FT_HAS_KERNING(face)) {
      FT_Vector kern;
      if (FT_Get_Kerning(face, previous, glyph, FT_KERNING_DEFAULT, &kern) == 0) pen += kern.x;
    }
    previous = glyph;
    if (FT_Load_Glyph(face, glyph, kLoadFlags) != 0) continue;
    on_glyph(pen);
    pen += face->glyph->advance.x;
  }
  return pen;
}

int measure_locked(FT_Face face, const std::u32string& text, int size_px) {
  FT_Set_Pixel_Sizes(face, 0, static_cast<FT_UInt>(size_px));
  return static_cast<int>((walk_glyphs(face, text, 0, [](long) {}) + 63) / 64);
}

void draw_locked(FT_Face face, Image& image, const std::u32string& text, int x, int baseline_y,
                 int size_px, const Rgba& rgba) {
  FT_Set_Pixel_Sizes(face, 0, static_cast<FT_UInt>(size_px));
  const double color[3] = {255.0 * std::clamp(rgba[0], 0.0, 1.0),
                           255.0 * std::clamp(rgba[1], 0.0, 1.0),
                           255.0 * std::clamp(rgba[2], 0.0, 1.0)};
  const double alpha = std::clamp(rgba[3], 0.0, 1.0);
  walk_glyphs(face, text, static_cast<long>(x) * 64, [&](long pen) {
    if (FT_Render_Glyph(face->glyph, FT_RENDER_MODE_NORMAL) != 0) return;
    const FT_GlyphSlot slot = face->glyph;
    const FT_Bitmap& bm = slot->bitmap;
    const int x0 = static_cast<int>((pen + 32) / 64) + slot->bitmap_left;
    const int y0 = baseline_y - slot->bitmap_top;
    for (unsigned row = 0; row < bm.rows; ++row) {
      const int y = y0 + static_cast<int>(row);
      if (y < 0 || y >= image.height) continue;
      for (unsigned col = 0; col < bm.width; ++col) {
        const int xx = x0 + static_cast<int>(col);
        if (xx < 0 || xx >= image.width) continue;
        const double cov = alpha * bm.buffer[row * bm.pitch + col] / 255.0;
        if (cov <= 0.0) continue;
        std::uint8_t* px = image.pixel(xx, y);
        for (int c = 0; c < 3; ++c)
          px[c] = static_cast<std::uint8_t>(std::lround(px[c] * (1.0 - cov) + color[c] * cov));
        px[3] = static_cast<std::uint8_t>(std::lround(px[3] + (255 - px[3]) * cov));
      }
    }
  });
}

}  // namespace

std::string caption_font_path() {
  const char* env = std::getenv("CORDGRASP_FONT");
  return env && *env ? std::string(env) : std::string(CORDGRASP_CAPTION_FONT);
}

bool caption_font_available() { return Font::instance().face() != nullptr; }

int measure_text(const std::string& text, int size_px) {
  Font& font = Font::instance();
  if (!font.face() || size_px <= 0) return 0;
  std::lock_guard<std::mutex> lock(font.mutex());
  return measure_locked(font.face(), decode_utf8(text), size_px);
}

bool draw_text(Image& image, const std::string& text, int x, int baseline_y, int size_px,
               const Rgba& rgba) {
  Font& font = Font::instance();
  if (!font.face()) return false;
  if (size_px <= 0) return true;
  std::lock_guard<std::mutex> lock(font.mutex());
  draw_locked(font.face(), image, decode_utf8(text), x, baseline_y, size_px, rgba);
  return true;
}

bool draw_text_centered(Image& image, const std::string& text, int x, int y, int w, int h,
                        int size_px, int pad_px, const Rgba& rgba) {
  Font& font = Font::instance();
  if (!font.face()) return false;
  std::lock_guard<std::mutex> lock(font.mutex());
  FT_Face face = font.face();
  constexpr int kMinSizePx = 8;
  const int avail = std::max(1, w - 2 * pad_px);
  std::u32string u = decode_utf8(text);
  int size = std::max(1, size_px);
  while (size > kMinSizePx && measure_locked(face, u, size) > avail) --size;
  if (measure_locked(face, u, size) > avail) {
    // Elide from the end until "text…" fits.
    while (!u.empty() && measure_locked(face, u + U"\u2026", size) > avail) u.pop_back();
    u += U"\u2026";
  }
  const int width = measure_locked(face, u, size);
  // Vertically centre the cap height (about 0.73 em for DejaVu Sans) in the band.
  const int baseline = y + static_cast<int>(std::lround(0.5 * h + 0.5 * 0.73 * size));
  draw_locked(face, image, u, x + (w - width) / 2, baseline, size, rgba);
  return true;
}

}  // namespace cordgrasp
