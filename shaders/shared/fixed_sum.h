// A sample's channel as the GPU adds it to a pixel's exact sum: in float, as render.comp computes
// it (the host's double version, with the same result for every float, is to_fixed in
// host/base/sample_sum.h). Shared so that the kernel probe runs the shader's very code on
// samples a render rarely makes: NaN, infinities, negatives, the limits.
#ifndef RTVK_FIXED_SUM_H
#define RTVK_FIXED_SUM_H
#include "kernel_lang.h"

RTVK_KERNELS_BEGIN

// Whether c is neither NaN nor infinite, by the bits (a driver may assume no float is NaN or
// infinite and fold a test of one). A sample that is not is dropped: it adds black, and the
// render counts it (render_status::dropped_samples).
inline bool sample_is_finite(float c) {
  return (floatBitsToUint(c) & 0x7f800000u) != 0x7f800000u;  // the exponent is not all ones
}

// Whether finite c is past the limit, by the bits: for floats that are not NaN and not negative
// the bit patterns order like the values, and a driver may fold a comparison with NaN or
// infinity. Such a sample fails the render (sample_sum.h); infinities are dropped instead.
inline bool sum_overflows(float c, float limit) {
  uint bits = floatBitsToUint(c);
  bool negative = (bits & 0x80000000u) != 0u;
  return sample_is_finite(c) && !negative && bits > floatBitsToUint(limit);
}

// floor(c * scale) as (low word, high word, top word) of a 96-bit integer, scale = 2^F: the
// scaling is by a power of two, floor(x / 2^64), floor(x / 2^32) and the differences are exact
// in float (each keeps bits x already has), and only the bits below 2^-F are dropped. NaN,
// negatives and values past the limit add 0, told apart by their bits (uint(NaN) would corrupt
// the sum).
inline uvec3 to_fixed(float c, float limit, float scale) {
  uint bits = floatBitsToUint(c);
  bool negative = (bits & 0x80000000u) != 0u;
  bool zero = !sample_is_finite(c) || negative || sum_overflows(c, limit);
  precise float x = (zero ? 0.0f : c) * scale;
  precise float t = floor(x * (1.0f / 18446744073709551616.0f));
  precise float r = x - t * 18446744073709551616.0f;
  precise float h = floor(r * (1.0f / 4294967296.0f));
  precise float l = r - h * 4294967296.0f;
  return uvec3(uint(l), uint(h), uint(t));
}

RTVK_KERNELS_END

#endif  // RTVK_FIXED_SUM_H
