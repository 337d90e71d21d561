#include "byte_encoding.h"

#include <cmath>

#include "view_transform.h"

namespace rtvk {

double encode_gamma(double c, double gamma) {
  if (gamma == 1) return c;
  if (gamma == 2) return std::sqrt(c);
  return std::pow(c, 1 / gamma);
}

namespace {

struct transform_word {
  view_transform t;
  const char* name;
};
constexpr transform_word transform_words[] = {{view_transform::standard, "standard"},
                                              {view_transform::filmic, "filmic"},
                                              {view_transform::agx, "agx"},
                                              {view_transform::linear, "linear"},
                                              {view_transform::gamma, "gamma"}};

static_assert(unsigned(view_transform::gamma) == RTVK_VIEW_GAMMA);
static_assert(unsigned(view_transform::standard) == RTVK_VIEW_STANDARD);
static_assert(unsigned(view_transform::filmic) == RTVK_VIEW_FILMIC);
static_assert(unsigned(view_transform::agx) == RTVK_VIEW_AGX);
static_assert(unsigned(view_transform::linear) == RTVK_VIEW_LINEAR);

// The exposure's factor; exactly 1 at 0 EV, so the books' bytes do not move.
double exposed(double c, double exposure) {
  return exposure == 0 ? c : c * std::exp2(exposure);
}

}  // namespace

const char* view_transform_name(view_transform t) {
  for (const transform_word& w : transform_words)
    if (w.t == t) return w.name;
  return "?";
}

std::optional<view_transform> view_transform_from_name(std::string_view name) {
  for (const transform_word& w : transform_words)
    if (name == w.name) return w.t;
  return std::nullopt;
}

double encode_channel(double c, const display_encoding& e) {
  c = exposed(c, e.exposure);
  switch (e.transform) {
    case view_transform::gamma:
      return encode_gamma(c, e.gamma);
    case view_transform::standard:
      return srgb_encode(c);
    case view_transform::filmic:
      return srgb_encode(filmic_display(c));
    case view_transform::linear:
      return c;
    case view_transform::agx:
      break;  // not per channel: encode_color
  }
  return srgb_encode(agx_display(real3(c)).x);
}

std::array<std::uint8_t, 3> encode_color(double r, double g, double b, const display_encoding& e) {
  if (e.per_channel())
    return {to_byte(encode_channel(r, e)), to_byte(encode_channel(g, e)),
            to_byte(encode_channel(b, e))};
  const real3 d =
      agx_display(real3(exposed(r, e.exposure), exposed(g, e.exposure), exposed(b, e.exposure)));
  return {to_byte(srgb_encode(d.x)), to_byte(srgb_encode(d.y)), to_byte(srgb_encode(d.z))};
}

byte_thresholds make_byte_thresholds(double gamma, int exponent) {
  return make_byte_thresholds(display_encoding{view_transform::gamma, gamma, 0}, exponent);
}

byte_thresholds make_byte_thresholds(const display_encoding& e, int exponent) {
  const auto byte_of = [&](std::uint64_t m) {
    return to_byte(encode_channel(std::ldexp(double(m), -exponent), e));
  };
  // The first mean whose byte is 255 is at most `top`: 2^F (a mean of 1) doubled until its byte
  // is 255 (2^(F - exposure) times filmic's 5.6 at most, within 2^63 for exposures >= -16).
  std::uint64_t top = exponent > 0 ? std::uint64_t(1) << exponent : 1;
  while (byte_of(top) < 255 && top < (std::uint64_t(1) << 62)) top *= 2;
  byte_thresholds t{};
  for (int k = 1; k < 256; ++k) {
    std::uint64_t lo = t[k - 1], hi = top;  // byte_of(hi) >= k; the answer is in [lo, hi]
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
