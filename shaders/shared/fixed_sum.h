// A sample's channel as the GPU adds it to a pixel's exact sum: in float, as render.comp computes
// it (the host's double version, with the same result for every float, is to_fixed in
// host/base/sample_sum.h). Shared so that the kernel probe runs the shader's very code on
// samples a render rarely makes: NaN, infinities, negatives, the limits.
#ifndef RTVK_FIXED_SUM_H
#define RTVK_FIXED_SUM_H
#include "kernel_lang.h"

RTVK_KERNELS_BEGIN

// floor(c * scale) as (low word, high word), scale = 2^F: the scaling is by a power of two,
// floor(x / 2^32) and x - h * 2^32 are exact in float, and only the bits below 2^-F are dropped.
// c is clamped into [0, limit] first: NaN and anything negative to 0, +infinity to the limit,
// told apart by their bits (a driver may assume no float is NaN and fold comparisons with one,
// and uint(NaN) would corrupt the 64-bit sum).
inline uvec2 to_fixed(float c, float limit, float scale) {
  uint bits = floatBitsToUint(c);
  bool not_a_number = (bits & 0x7fffffffu) > 0x7f800000u;
  bool negative = (bits & 0x80000000u) != 0u;
  precise float x = (not_a_number || negative ? 0.0f : min(c, limit)) * scale;
  precise float h = floor(x * (1.0f / 4294967296.0f));
  precise float l = x - h * 4294967296.0f;
  return uvec2(uint(l), uint(h));
}

RTVK_KERNELS_END

#endif  // RTVK_FIXED_SUM_H
