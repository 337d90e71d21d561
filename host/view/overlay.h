#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace rtvk::view {

// Draws lines of text into RGBA8 pixels (red in the low byte, rows from the top), white on a
// dark band at the top left, with stb_easy_font's segment font (about 7 pixels a line, drawn
// twice as large where the image is at least 640 wide). For the window only: screenshots are
// the render without it. Returns the rows it drew over.
int draw_overlay(std::vector<std::uint32_t>& rgba, int width, int height,
                 const std::vector<std::string>& lines);

}  // namespace rtvk::view
