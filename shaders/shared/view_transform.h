// The view transforms: what turns a pixel's scene-linear mean (after exposure) into the display
// value [0, 1] that to_byte quantizes (docs/color.md). Written once: the host encodes files and
// builds the byte thresholds with it (host/base/byte_encoding.cpp, in double), and tonemap.comp
// runs agx_display on the device (in float) for the one transform no threshold table can encode,
// because AgX mixes the channels.
#ifndef RTVK_VIEW_TRANSFORM_H
#define RTVK_VIEW_TRANSFORM_H
#include "kernel_lang.h"

// view_transform's values (host/base/byte_encoding.h), and tonemap_push::transform's.
#define RTVK_VIEW_GAMMA 0u     // the books' power law c^(1/gamma)
#define RTVK_VIEW_STANDARD 1u  // the sRGB transfer function (IEC 61966-2-1)
#define RTVK_VIEW_FILMIC 2u    // Hable's filmic curve, per channel, then sRGB
#define RTVK_VIEW_AGX 3u       // Blender 4's AgX (inset, log2, sigmoid, outset), then sRGB
#define RTVK_VIEW_LINEAR 4u    // no curve

RTVK_KERNELS_BEGIN

// The sRGB transfer function (IEC 61966-2-1's encoding): linear light to the display's signal,
// a line of slope 12.92 up to 0.0031308, then 1.055 c^(1/2.4) - 0.055. 0 for c <= 0 (and NaN).
inline real srgb_encode(real c) {
  if (!(c > real(0.0))) return real(0.0);
  if (c <= real(0.0031308)) return real(12.92) * c;
  return real(1.055) * pow(c, real(1.0 / 2.4)) - real(0.055);
}

// John Hable's filmic curve ("Filmic Tonemapping Operators", 2010; Uncharted 2), one channel:
// a toe, a straight middle and a shoulder that reaches white at W = 11.2, after his exposure
// bias of 2. Increasing for c >= 0 (its derivative's numerator, 0.0675 x^2 + 0.0168 x + 0.001,
// is positive), so byte thresholds encode it exactly; display-linear, sRGB follows.
inline real hable_partial(real x) {
  const real A = real(0.15), B = real(0.50), C = real(0.10), D = real(0.20), E = real(0.02),
             F = real(0.30);
  return (x * (A * x + C * B) + D * E) / (x * (A * x + B) + D * F) - E / F;
}
inline real filmic_display(real c) {
  if (!(c > real(0.0))) return real(0.0);
  return hable_partial(real(2.0) * c) / hable_partial(real(11.2));
}

// AgX's tone scale (Eary Chow's, as Blender 4 builds its AgX Base LUT): on the log2 encoding x
// in [0, 1], a sigmoid through (0, 0), the pivot (x_p, y_p) with slope 2.4 there, and (1, 1):
//   y = y_p + s d / (1 + (s |d| / k)^1.5)^(1/1.5), d = x - x_p,
// its scale k chosen below and above the pivot so that the curve ends at 0 and at 1. The pivot
// is mid grey: 0.18 sits 10 of the encoding's 16.5 stops up, and y_p^2.4 = 0.18.
inline real agx_sigmoid(real x) {
  const real s = real(2.4), p = real(1.5);
  const real x_p = real(10.0 / 16.5);
  real y_p = pow(real(0.18), real(1.0 / 2.4));
  real d = x - x_p;
  // s |d| / k at the curve's end on this side: (s |d_end| / y_end)^p - 1 = (s |d_end| / k)^p.
  real reach = d < real(0.0) ? s * x_p / y_p : s * (real(1.0) - x_p) / (real(1.0) - y_p);
  real end = d < real(0.0) ? x_p : real(1.0) - x_p;
  real k = s * end / pow(pow(reach, p) - real(1.0), real(1.0) / p);
  return y_p + s * d / pow(real(1.0) + pow(s * abs(d) / k, p), real(1.0) / p);
}

// A channel of AgX's log2 encoding: -10 to +6.5 stops around mid grey 0.18, clamped to [0, 1].
inline real agx_log2(real c) {
  const real lo = real(-12.47393118833241);  // log2(0.18) - 10
  const real hi = real(4.026068811667588);   // log2(0.18) + 6.5
  real l = log2(max(c, real(1e-10)));
  return min(max((l - lo) / (hi - lo), real(0.0)), real(1.0));
}

// A 3x3 matrix given by its rows, times v.
inline real3 rows_times(real3 r0, real3 r1, real3 r2, real3 v) {
  return real3(r0.x * v.x + r0.y * v.y + r0.z * v.z, r1.x * v.x + r1.y * v.y + r1.z * v.z,
               r2.x * v.x + r2.y * v.y + r2.z * v.z);
}

// AgX as Blender 4 defines it, for a linear Rec.709 (sRGB primaries) color: to Rec.2020 (the
// primaries of ITU-R BT.2087, from the chromaticities), the inset matrix (rows summing to 1, so
// greys stay grey and pure primaries are pulled inward: bright saturated colors go to white
// along their own hue instead of skewing to the channel that clips last), the log2 encoding
// and the sigmoid per channel, the power 2.4 back to linear, the outset matrix (restoring
// chroma) and back to Rec.709. The inset and outset matrices are Blender's as Filament's AgX
// publishes them (google/filament PR 7236). Negative input is clamped to 0 first; the result
// is clamped to [0, 1]: display-linear, sRGB follows. Simplified as Filament, three.js and
// Godot are: no "guard rails" for negatives, no hue mix of Blender's LUT script.
inline real3 agx_display(real3 c) {
  c = max(c, real3(real(0.0)));
  c = rows_times(
      real3(real(0.6274038959346990), real(0.3292830383778840), real(0.0433130656874170)),
      real3(real(0.0690972893582320), real(0.9195403950754590), real(0.0113623155663090)),
      real3(real(0.0163914388751500), real(0.0880133078772260), real(0.8955952532476240)), c);
  c = rows_times(real3(real(0.856627153315983), real(0.0951212405381588), real(0.0482516061458583)),
                 real3(real(0.137318972929847), real(0.761241990602591), real(0.101439036467562)),
                 real3(real(0.11189821299995), real(0.0767994186031903), real(0.811302368396859)),
                 c);
  c = real3(agx_sigmoid(agx_log2(c.x)), agx_sigmoid(agx_log2(c.y)), agx_sigmoid(agx_log2(c.z)));
  c = max(c, real3(real(0.0)));  // the toe ends at 0, give or take a rounding
  c = real3(pow(c.x, real(2.4)), pow(c.y, real(2.4)), pow(c.z, real(2.4)));
  c = rows_times(
      real3(real(1.1271005818144368), real(-0.11060664309660323), real(-0.016493938717834573)),
      real3(real(-0.1413297634984383), real(1.157823702216272), real(-0.016493938717834257)),
      real3(real(-0.14132976349843826), real(-0.11060664309660294), real(1.2519364065950405)), c);
  c = rows_times(real3(real(1.660491002108434), real(-0.587641138788549), real(-0.072849863319885)),
                 real3(real(-0.124550474521591), real(1.132899897125960), real(-0.008349422604369)),
                 real3(real(-0.018150763354905), real(-0.100578898008007), real(1.118729661362912)),
                 c);
  return min(max(c, real3(real(0.0))), real3(real(1.0)));
}

RTVK_KERNELS_END

#endif  // RTVK_VIEW_TRANSFORM_H
