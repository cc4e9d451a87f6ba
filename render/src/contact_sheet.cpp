#include "cordgrasp/render/contact_sheet.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "cordgrasp/render/text.h"

namespace cordgrasp {

Image compose_contact_sheet(const std::vector<Image>& tiles,
                            const std::vector<std::string>& captions,
                            const ContactSheetParams& params) {
  if (tiles.empty()) throw std::invalid_argument("compose_contact_sheet: no tiles");
  const int n = static_cast<int>(tiles.size());
  const int cols = params.columns > 0
                       ? std::min(params.columns, n)
                       : static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
  const int rows = (n + cols - 1) / cols;
  int cell_w = 0, cell_h = 0;
  for (const Image& t : tiles) {
    cell_w = std::max(cell_w, t.width);
    cell_h = std::max(cell_h, t.height);
  }
  const bool fonts = caption_font_available();
  const bool any_caption = fonts && std::any_of(captions.begin(), captions.end(),
                                                [](const auto& c) { return !c.empty(); });
  const int caption_h =
      any_caption ? static_cast<int>(std::lround(1.7 * params.caption_size_px)) : 0;
  const int title_h = fonts && !params.title.empty()
                          ? static_cast<int>(std::lround(1.8 * params.title_size_px))
                          : 0;
  const int gap = std::max(0, params.spacing_px);
  const int width = gap + cols * (cell_w + gap);
  const int height = gap + title_h + rows * (cell_h + caption_h + gap);
  Image sheet = make_image(width, height);
  if (title_h > 0)
    draw_text_centered(sheet, params.title, 0, gap, width, title_h, params.title_size_px, gap);
  for (int i = 0; i < n; ++i) {
    const int cx = gap + (i % cols) * (cell_w + gap);
    const int cy = gap + title_h + (i / cols) * (cell_h + caption_h + gap);
    const Image& t = tiles[i];
    blit_image(sheet, t, cx + (cell_w - t.width) / 2, cy + (cell_h - t.height) / 2);
    if (caption_h > 0 && i < static_cast<int>(captions.size()) && !captions[i].empty())
      draw_text_centered(sheet, captions[i], cx, cy + cell_h, cell_w, caption_h,
                         params.caption_size_px, 4);
  }
  return sheet;
}

}  // namespace cordgrasp
