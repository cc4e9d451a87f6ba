#pragma once
#include <string>

#include "cordgrasp/render/image.h"
#include "cordgrasp/render/scene.h"

namespace cordgrasp {

/// Path of the caption font: $CORDGRASP_FONT if set, else DejaVu Sans (fonts-dejavu-core).
std::string caption_font_path();

/// True when the caption font loads; a font that fails is warned about once on stderr.
bool caption_font_available();

/// Width [px] of one line of UTF-8 `text` at font size `size_px`; 0 without a font.
int measure_text(const std::string& text, int size_px);

/// Draws one line of UTF-8 `text` (FreeType, anti-aliased) with the left end of its baseline
/// at (x, baseline_y) px, alpha-blended, clipped to the image. Returns false (and draws
/// nothing) when no font is available.
bool draw_text(Image& image, const std::string& text, int x, int baseline_y, int size_px,
               const Rgba& rgba = Rgba(0.15, 0.15, 0.15, 1.0));

/// Draws one line of `text` centred in the box [x, x + w) × [y, y + h) px, shrinking the font
/// (down to 8 px) and then eliding with "…" so it fits the width less `pad_px` each side.
/// Returns false when no font is available.
bool draw_text_centered(Image& image, const std::string& text, int x, int y, int w, int h,
                        int size_px, int pad_px = 8,
                        const Rgba& rgba = Rgba(0.15, 0.15, 0.15, 1.0));

}  // namespace cordgrasp
