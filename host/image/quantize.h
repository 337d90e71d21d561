#pragma once
#include <cstdint>

#include "byte_encoding.h"
#include "framebuffer.h"
#include "image_rgb8.h"

namespace rtvk {

// Each channel through encode_gamma (1: none, as the lesson; 2: the book's square root), then
// to_byte.
image_rgb8 quantize(const framebuffer& fb, double gamma = 1);

// Each pixel through the encoding's exposure and view transform (encode_color), then to_byte:
// the gamma transform at 0 EV gives quantize(fb, e.gamma)'s bytes.
image_rgb8 quantize(const framebuffer& fb, const display_encoding& e);

}  // namespace rtvk
