#pragma once
#include <cstdint>

#include "byte_encoding.h"
#include "framebuffer.h"
#include "image_rgb8.h"

namespace rtvk {

// Each channel through encode_gamma (1: none, as the lesson; 2: the book's square root), then
// to_byte.
image_rgb8 quantize(const framebuffer& fb, double gamma = 1);

}  // namespace rtvk
