#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace rtvk {

// A pixel's samples summed exactly. Each channel of each sample becomes the 64-bit fixed-point
// number floor(c * 2^F), and integers add without rounding: a sum does not depend on the order
// in which its samples were added or how they were batched, and its error is one truncation per
// sample (< 2^-F each, so < 2^-F in the mean), however many samples there are. The GPU engine
// sums this way (shaders/render.comp); the host divides and encodes (here, byte_encoding.h).

inline constexpr int max_sum_samples_log2 = 20;  // samples per pixel a sum has room for: max_spp

// F for a scene whose samples are at most `brightest` in any channel (at least 1: the normal
// material's 1): 2^20 samples of up to twice that fit 63 bits. 42 for the built-in scenes.
inline int sum_exponent(double brightest) {
  const int e = brightest > 1 ? int(std::ceil(std::log2(brightest))) : 0;
  return 63 - max_sum_samples_log2 - 1 - e;
}

// The largest sample channel value a sum of exponent F accepts (larger ones are clamped to it).
inline double sum_sample_limit(int exponent) {
  return std::ldexp(1.0, 63 - max_sum_samples_log2 - exponent);
}

// One sample channel as the shader converts it (to_fixed in render.comp): floor(c * 2^F), after
// clamping c into [0, sum_sample_limit(F)] (NaN to 0).
inline std::uint64_t to_fixed(float c, int exponent) {
  if (!(c > 0)) return 0;
  const double x = std::ldexp(std::min(double(c), sum_sample_limit(exponent)), exponent);
  return std::uint64_t(std::floor(x));
}

// The mean of `samples` samples whose fixed-point sum is `sum`.
inline double sum_mean(std::uint64_t sum, std::uint32_t samples, int exponent) {
  return samples == 0 ? 0.0 : std::ldexp(double(sum), -exponent) / double(samples);
}

}  // namespace rtvk
