#pragma once
#include <array>
#include <cstdint>

#include "sample_sum.h"

namespace rtvk {

// One channel to 8 bits as the lesson writes it: int(255.999 * c), after clamping to [0, 1].
// NaN maps to 0. Both backends' means go through this one function.
inline std::uint8_t to_byte(double c) {
  if (!(c > 0.0)) return 0;
  if (c >= 1.0) return 255;
  return static_cast<std::uint8_t>(255.999 * c);
}

// Gamma encoding: 1 leaves c as it is (the lesson), 2 is the book's square root.
double encode_gamma(double c, double gamma);

// to_byte(encode_gamma(mean, gamma)) for a fixed-point sum (sample_sum.h), computed with
// integers only, so the shader (tonemap.comp) and the host get the same byte on any device:
// thresholds[k] is the smallest fixed-point mean M with to_byte(encode_gamma(M * 2^-F)) >= k,
// and a pixel's byte is the largest k with sum >= thresholds[k] * samples (floor(sum / samples)
// >= thresholds[k]). thresholds[0] is 0.
using byte_thresholds = std::array<std::uint64_t, 256>;
byte_thresholds make_byte_thresholds(double gamma, int exponent);

// The byte for a sum of `samples` samples (0 when there are none), by binary search over the
// thresholds, exactly as tonemap.comp does it.
std::uint8_t encode_sum(exact_sum sum, std::uint32_t samples, const byte_thresholds& t);

}  // namespace rtvk
