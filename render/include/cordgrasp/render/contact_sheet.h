#pragma once
#include <string>
#include <vector>

#include "cordgrasp/render/image.h"

namespace cordgrasp {

/// Layout of a contact sheet.
struct ContactSheetParams {
  int columns = 0;           ///< tiles per row; 0: ceil(sqrt(N))
  int spacing_px = 12;       ///< gap between tiles and around the border [px]
  int caption_size_px = 16;  ///< font size of the per-tile captions [px]
  std::string title;         ///< optional line above the grid
  int title_size_px = 20;    ///< [px]
};

/// Composes `tiles` into a grid (row-major, each cell as large as the largest tile, tiles
/// centred) on white, with `captions[i]` (may be empty or shorter than tiles) under tile i.
/// @throws std::invalid_argument when `tiles` is empty.
Image compose_contact_sheet(const std::vector<Image>& tiles,
                            const std::vector<std::string>& captions = {},
                            const ContactSheetParams& params = {});

}  // namespace cordgrasp
