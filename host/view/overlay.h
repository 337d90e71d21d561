#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace rtvk::view {

// The overlay's text as a bit mask over a band at the top left of the image: white where a bit
// is set, the render darkened under the rest (overlay.comp composes it on the device). Drawn with
// stb_easy_font's segment font (about 7 pixels a line, twice as large where the image is at
// least 640 wide). For the window only: screenshots are the render without it.
struct overlay_mask {
  int width = 0, height = 0;        // the band, pixels (within the image)
  int words_per_row = 0;            // 32-bit words of `bits` per band row
  std::vector<std::uint32_t> bits;  // bit x % 32 of word y * words_per_row + x / 32
  bool at(int x, int y) const {     // whether pixel (x, y) of the band is text
    return (bits[std::size_t(y) * std::size_t(words_per_row) + std::size_t(x) / 32] >> (x % 32)) &
           1u;
  }
};

overlay_mask draw_overlay(int image_width, int image_height, const std::vector<std::string>& lines);

}  // namespace rtvk::view
