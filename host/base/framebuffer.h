#pragma once
#include <cstddef>
#include <vector>

#include "vec3.h"

namespace rtvk {

// Linear RGB pixels, row 0 at the top of the image. Held in double so the CPU reference
// quantizes exactly as the lesson does; the GPU's floats widen into it without loss.
class framebuffer {
 public:
  framebuffer(int width, int height)
      : width_(width), height_(height), pixels_(std::size_t(width) * std::size_t(height)) {}

  int width() const { return width_; }
  int height() const { return height_; }
  color& at(int x, int y) { return pixels_[index(x, y)]; }
  const color& at(int x, int y) const { return pixels_[index(x, y)]; }

 private:
  std::size_t index(int x, int y) const { return std::size_t(y) * std::size_t(width_) + x; }

  int width_;                  // pixels
  int height_;                 // pixels
  std::vector<color> pixels_;  // width * height, row-major from the top
};

}  // namespace rtvk
