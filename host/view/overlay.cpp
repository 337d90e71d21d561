#include "overlay.h"

#include <algorithm>
#include <cstring>

// stb_easy_font's functions are static (and some unused here); its buffers are char*.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#include <stb_easy_font.h>
#pragma GCC diagnostic pop

namespace rtvk::view {
namespace {

void fill(std::vector<std::uint32_t>& rgba, int width, int height, int x0, int y0, int x1, int y1,
          std::uint32_t color) {
  x0 = std::clamp(x0, 0, width);
  x1 = std::clamp(x1, 0, width);
  y0 = std::clamp(y0, 0, height);
  y1 = std::clamp(y1, 0, height);
  for (int y = y0; y < y1; ++y)
    std::fill(rgba.begin() + std::ptrdiff_t(y) * width + x0,
              rgba.begin() + std::ptrdiff_t(y) * width + x1, color);
}

}  // namespace

int draw_overlay(std::vector<std::uint32_t>& rgba, int width, int height,
                 const std::vector<std::string>& lines) {
  const int scale = width >= 640 ? 2 : 1;
  constexpr int line_height = 10, margin = 4;
  int text_width = 0;
  for (const std::string& l : lines) {
    std::string copy = l;
    text_width = std::max(text_width, stb_easy_font_width(copy.data()));
  }
  const int band_h = (int(lines.size()) * line_height + 2 * margin) * scale;
  const int band_w = (text_width + 2 * margin) * scale;
  // Darken the band rather than blank it: the render stays faintly visible behind the text.
  for (int y = 0; y < std::min(band_h, height); ++y)
    for (int x = 0; x < std::min(band_w, width); ++x) {
      std::uint32_t& p = rgba[std::size_t(y) * std::size_t(width) + std::size_t(x)];
      p = 0xff000000u | ((p >> 2) & 0x003f3f3fu);
    }
  static char vertices[60000];  // 16 bytes a vertex, 4 a quad: ~900 quads, ~80 characters a line
  for (std::size_t i = 0; i < lines.size(); ++i) {
    std::string text = lines[i];
    unsigned char white[4] = {255, 255, 255, 255};
    const int quads = stb_easy_font_print(float(margin), float(margin + int(i) * line_height),
                                          text.data(), white, vertices, sizeof vertices);
    for (int q = 0; q < quads; ++q) {
      float v0[2], v2[2];  // a quad's first (top left) and third (bottom right) vertex
      std::memcpy(v0, vertices + q * 64, sizeof v0);
      std::memcpy(v2, vertices + q * 64 + 32, sizeof v2);
      fill(rgba, width, height, int(v0[0]) * scale, int(v0[1]) * scale, int(v2[0]) * scale,
           int(v2[1]) * scale, 0xffffffffu);
    }
  }
  return std::min(band_h, height);
}

}  // namespace rtvk::view
