#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace rtvk {

// A pixel's samples summed exactly. Each channel of each sample becomes the fixed-point number
// floor(c * 2^F), and integers add without rounding: a sum does not depend on the order in which
// its samples were added, how they were batched, or how sample ranges were split and merged, and
// its error is one truncation per sample (< 2^-F each, so < 2^-F in the mean), however many
// samples there are. The GPU engine sums this way (shaders/render.comp); the host divides and
// encodes (here, byte_encoding.h).
//
// A channel's sum has 96 bits (three 32-bit words on the device), F = 42 fractional bits for
// every scene whose brightest emitter is at most 2^32: one sample adds anything from 2^-42
// (2.3e-13) to 2^33 (8.6e9) exactly, so a lamp of 10^6 and a shadow of 10^-6 add up in the same
// pixel without either being clamped or rounded away. Why this scheme: float partial sums depend
// on the order of the additions, and an exponent chosen per pixel or per tile as bright samples
// arrive makes the bits kept depend on when they arrived (batching) and on where a farm split
// the samples. A finite sample brighter than the limit (a firefly 2^33 times the scene's
// brightest) is not clamped into bias: the render fails, saying so (sample_overflow_error). A
// sample with a NaN or infinite channel is dropped: it adds black, and the render counts it.
__extension__ typedef unsigned __int128 exact_sum;  // a channel's sum; 96 bits are used

inline constexpr int max_sum_samples_log2 = 20;  // samples per pixel a sum has room for: max_spp
inline constexpr int sum_bits = 96;              // bits of a channel's sum
inline constexpr int sum_fraction_bits = 42;     // F, unless the scene is brighter than 2^32

// F for a scene whose samples are at most `brightest` in any channel (at least 1: the normal
// material's 1): 42, lower only where 2^20 samples of twice the brightest would not fit 95 bits.
inline int sum_exponent(double brightest) {
  const int e = brightest > 1 ? int(std::ceil(std::log2(brightest))) : 0;
  return std::min(sum_fraction_bits, sum_bits - 1 - max_sum_samples_log2 - 1 - e);
}

// The largest sample channel value a sum of exponent F accepts: 2^20 of them fit 95 bits.
inline double sum_sample_limit(int exponent) {
  return std::ldexp(1.0, sum_bits - 1 - max_sum_samples_log2 - exponent);
}

// Whether a finite channel value is past the limit: the shader's sum_overflows
// (shaders/shared/fixed_sum.h). NaN, infinities and negatives are not: they add 0.
inline bool sum_overflows(float c, int exponent) {
  return std::isfinite(c) && c > sum_sample_limit(exponent);
}

// One sample channel as the shader converts it (to_fixed in fixed_sum.h): floor(c * 2^F); 0 for
// NaN, infinities, negatives and values past the limit (which fail the render instead).
inline exact_sum to_fixed(float c, int exponent) {
  if (!std::isfinite(c)) return 0;
  if (!(c > 0) || sum_overflows(c, exponent)) return 0;
  return exact_sum(std::floor(std::ldexp(double(c), exponent)));  // exact: 24 bits, < 2^76
}

// A channel's sum from its three 32-bit words, least significant first.
inline exact_sum channel_sum(std::uint32_t low, std::uint32_t high, std::uint32_t top) {
  return exact_sum(top) << 64 | exact_sum(high) << 32 | low;
}

// The mean of `samples` samples whose fixed-point sum is `sum`.
inline double sum_mean(exact_sum sum, std::uint32_t samples, int exponent) {
  return samples == 0 ? 0.0 : std::ldexp(double(sum), -exponent) / double(samples);
}

}  // namespace rtvk
