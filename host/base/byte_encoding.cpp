#include "byte_encoding.h"

#include <cmath>

namespace rtvk {

double encode_gamma(double c, double gamma) {
  if (gamma == 1) return c;
  if (gamma == 2) return std::sqrt(c);
  return std::pow(c, 1 / gamma);
}

byte_thresholds make_byte_thresholds(double gamma, int exponent) {
  // Means of 1 and above encode to 255, so every threshold lies in [0, 2^F] (at least 1).
  const std::uint64_t one = exponent > 0 ? std::uint64_t(1) << exponent : 1;
  const auto byte_of = [&](std::uint64_t m) {
    return to_byte(encode_gamma(std::ldexp(double(m), -exponent), gamma));
  };
  byte_thresholds t{};
  for (int k = 1; k < 256; ++k) {
    std::uint64_t lo = t[k - 1], hi = one;  // byte_of(hi) >= k; the answer is in [lo, hi]
    while (lo < hi) {
      const std::uint64_t mid = lo + (hi - lo) / 2;
      if (byte_of(mid) >= k)
        hi = mid;
      else
        lo = mid + 1;
    }
    t[k] = lo;
  }
  return t;
}

std::uint8_t encode_sum(exact_sum sum, std::uint32_t samples, const byte_thresholds& t) {
  if (samples == 0) return 0;
  std::uint32_t lo = 0, hi = 255;
  while (lo < hi) {
    const std::uint32_t mid = (lo + hi + 1) / 2;
    if (sum >= exact_sum(t[mid]) * samples)
      lo = mid;
    else
      hi = mid - 1;
  }
  return std::uint8_t(lo);
}

}  // namespace rtvk
