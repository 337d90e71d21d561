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

overlay_mask draw_overlay(int image_width, int image_height,
                          const std::vector<std::string>& lines) {
  const int scale = image_width >= 640 ? 2 : 1;
  constexpr int line_height = 10, margin = 4;
  int text_width = 0;
  for (const std::string& l : lines) {
    std::string copy = l;
    text_width = std::max(text_width, stb_easy_font_width(copy.data()));
  }
  overlay_mask m;
  m.height = std::min((int(lines.size()) * line_height + 2 * margin) * scale, image_height);
  m.width = std::min((text_width + 2 * margin) * scale, image_width);
  m.words_per_row = (m.width + 31) / 32;
  m.bits.assign(std::size_t(m.words_per_row) * std::size_t(m.height), 0);
  // A quad of stb_easy_font's, scaled and clipped to the band, set in the mask.
  const auto fill = [&m](int x0, int y0, int x1, int y1) {
    x0 = std::clamp(x0, 0, m.width);
    x1 = std::clamp(x1, 0, m.width);
    y0 = std::clamp(y0, 0, m.height);
    y1 = std::clamp(y1, 0, m.height);
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x)
        m.bits[std::size_t(y) * std::size_t(m.words_per_row) + std::size_t(x) / 32] |= 1u
                                                                                       << (x % 32);
  };
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
      fill(int(v0[0]) * scale, int(v0[1]) * scale, int(v2[0]) * scale, int(v2[1]) * scale);
    }
  }
  return m;
}

}  // namespace rtvk::view
