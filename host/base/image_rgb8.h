#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace rtvk {

// An 8-bit RGB image as written to disk, row 0 at the top.
struct image_rgb8 {
  int width = 0;                  // pixels
  int height = 0;                 // pixels
  std::vector<std::uint8_t> rgb;  // width * height * 3 bytes, row-major from the top

  std::size_t size_bytes() const { return std::size_t(width) * std::size_t(height) * 3; }
  const std::uint8_t* pixel(int x, int y) const {
    return rgb.data() + (std::size_t(y) * std::size_t(width) + x) * 3;
  }
};

}  // namespace rtvk
