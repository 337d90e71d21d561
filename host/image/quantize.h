#pragma once
#include <cstdint>

#include "framebuffer.h"
#include "image.h"

namespace rtvk {

// One channel to 8 bits as the lesson writes it: int(255.999 * c), after clamping to [0, 1].
// NaN maps to 0. Both backends go through this one function, so quantization never differs.
inline std::uint8_t to_byte(double c) {
  if (!(c > 0.0)) return 0;
  if (c >= 1.0) return 255;
  return static_cast<std::uint8_t>(255.999 * c);
}

// Encodes with the given gamma (1: none, as the lesson; 2: the book's square root), then to_byte.
image_rgb8 quantize(const framebuffer& fb, double gamma = 1);

}  // namespace rtvk
