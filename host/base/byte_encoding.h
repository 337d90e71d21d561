#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

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

// How scene-linear values become the display's (docs/color.md). The numbers are
// shaders/shared/view_transform.h's RTVK_VIEW_*, which tonemap.comp reads.
enum class view_transform : std::uint8_t {
  gamma = 0,     // the books' power law c^(1/gamma): the built-in scenes, files that set "gamma"
  standard = 1,  // the sRGB transfer function (IEC 61966-2-1): mesh files, new scene files
  filmic = 2,    // Hable's filmic curve per channel, then sRGB
  agx = 3,       // Blender 4's AgX, which mixes the channels, then sRGB
  linear = 4,    // no curve
};

// --view-transform's and "view_transform"'s words, and back; nullopt for any other word.
const char* view_transform_name(view_transform t);
std::optional<view_transform> view_transform_from_name(std::string_view name);
inline constexpr const char* view_transform_words = "standard, filmic, agx, linear or gamma";

// --exposure's range, EV: thresholds are 64-bit integers (2^(F - EV) for the brightest byte).
inline constexpr double max_exposure = 16;

// A render's encoding to 8 bits: the transform, the power law's gamma, and the exposure.
struct display_encoding {
  view_transform transform = view_transform::gamma;
  double gamma = 1;     // the power law's exponent's inverse (transform gamma only)
  double exposure = 0;  // EV: scene-linear values are multiplied by 2^exposure first

  // Whether each channel's byte depends on that channel alone, increasingly: all but AgX.
  bool per_channel() const { return transform != view_transform::agx; }
  bool operator==(const display_encoding&) const = default;
};

// A per-channel encoding's display value in [0, 1] (before to_byte) of a scene-linear value.
double encode_channel(double c, const display_encoding& e);
// Any encoding's bytes for a scene-linear color (AgX by shaders/shared/view_transform.h).
std::array<std::uint8_t, 3> encode_color(double r, double g, double b, const display_encoding& e);

// to_byte(encode_gamma(mean, gamma)) for a fixed-point sum (sample_sum.h), computed with
// integers only, so the shader (tonemap.comp) and the host get the same byte on any device:
// thresholds[k] is the smallest fixed-point mean M with to_byte(encode_gamma(M * 2^-F)) >= k,
// and a pixel's byte is the largest k with sum >= thresholds[k] * samples (floor(sum / samples)
// >= thresholds[k]). thresholds[0] is 0.
// Any per-channel encoding works so, its curve being increasing: the same for
// encode_channel(M * 2^-F, e), for which thresholds reach up to 2^(F - exposure) times the value
// whose byte is 255.
using byte_thresholds = std::array<std::uint64_t, 256>;
byte_thresholds make_byte_thresholds(double gamma, int exponent);
byte_thresholds make_byte_thresholds(const display_encoding& e, int exponent);

// The byte for a sum of `samples` samples (0 when there are none), by binary search over the
// thresholds, exactly as tonemap.comp does it.
std::uint8_t encode_sum(exact_sum sum, std::uint32_t samples, const byte_thresholds& t);

}  // namespace rtvk
