#pragma once
#include "camera.h"
#include "framebuffer.h"
#include "hittable.h"

namespace rtvk {

// Normalized coordinate of pixel i along a side of n pixels: i / (n - 1), as the lesson does,
// and the side's center when n == 1 (where the lesson would divide by zero).
inline double pixel_coordinate(int i, int n) {
  return n > 1 ? double(i) / (n - 1) : 0.5;
}

// The lesson's main loop: one ray per pixel, rows from the top.
framebuffer render_cpu(const camera& cam, const hittable& world);

}  // namespace rtvk
