// An HDR environment map: the light from infinitely far away that a ray sees when it escapes the
// scene, an equirectangular image (docs/lighting.md), and the importance sampler next-event
// estimation draws directions toward it with: a 2D piecewise-constant density over the texels,
// proportional to each texel's luminance times sin(latitude from the pole), by a marginal CDF over
// rows and a conditional CDF in each row (both made once on the host: environment_map.h).
//
// Lookups are nearest-texel, so the radiance is piecewise constant over the texels, as the density
// is: environment_pdf is exactly the density environment_sample draws with.
//
// The map's data is the backend's: GLSL reads `environment_texels[]` (RTVK_BINDING_ENVIRONMENT)
// and `environment_table[]` (RTVK_BINDING_ENVIRONMENT_CDF), which the including shader declares,
// C++ an environment_table passed along. Functions that read them take ENV_PARAM first and pass
// ENV on (pdf.h's LIGHTS_PARAM, LIGHTS).
//
// The texels: one uint each, Radiance's RGBE (red, green, blue mantissas in bits 0-23, the shared
// exponent e in bits 24-31: a channel is m * 2^(e - 136), black where e = 0, and e >= 10
// otherwise), row by row from the top (+y). Both backends decode the same words exactly.
// The table, floats: RTVK_ENV_HEADER words (the fields below), then the marginal CDF (height + 1
// entries, 0 to 1) and each row's conditional CDF (width + 1 entries, 0 to 1), rows from the top.
#ifndef RTVK_ENVIRONMENT_H
#define RTVK_ENVIRONMENT_H
#include "kernel_lang.h"
#include "light_sample.h"
#include "ray.h"

// The table's header, by word.
#define RTVK_ENV_WIDTH 0     // texels in a row (exact in float: at most 2^24)
#define RTVK_ENV_HEIGHT 1    // rows
#define RTVK_ENV_STRENGTH 2  // multiplies every texel's radiance
#define RTVK_ENV_COS 3       // cos(rotation about +y)
#define RTVK_ENV_SIN 4       // sin(rotation about +y)
#define RTVK_ENV_VISIBLE 5   // 1: camera rays that escape see the map; 0: the scene's sky
#define RTVK_ENV_TRIPS 6     // loop trips of environment_sample's two binary searches
#define RTVK_ENV_HEADER 8    // words of the header; the marginal CDF follows

RTVK_KERNELS_BEGIN

#ifdef __cplusplus
// The map as the C++ backends read it (host/scene/environment_map.h packs it).
struct environment_table {
  const uint* texels = nullptr;  // RGBE words, width x height, rows from the top
  const float* table = nullptr;  // header, marginal CDF, conditional CDFs
};
#define ENV_PARAM const environment_table &env_in,
#define ENV env_in,
#define ENV_ONLY const environment_table& env_in  // the parameter list of one that takes no other
#define ENV_ALONE env_in                          // and its argument
#define ENV_TEXEL(i) env_in.texels[i]
#define ENV_TABLE(i) real(env_in.table[i])
// 2^(e - 136): exact in either precision for the e an encoded texel has.
inline real rgbe_scale(uint e) {
  return std::ldexp(real(1.0), int(e) - 136);
}
#else
#define ENV_PARAM
#define ENV
#define ENV_ONLY
#define ENV_ALONE
#define ENV_TEXEL(i) environment_texels[i]
#define ENV_TABLE(i) environment_table[i]
// 2^(e - 136) built from its bits (a normal float for 10 <= e <= 255).
float rgbe_scale(uint e) {
  return uintBitsToFloat((e - 9u) << 23u);
}
#endif

const real environment_inv_pi = real(0.31830988618379067154);
const real environment_pi = real(3.14159265358979323846);
// The largest float below 1: a sampler's random number is clamped there, inside the last CDF step.
const real environment_below_one = real(0.99999994);

// Texel (x, y)'s radiance (without the strength), decoded from its RGBE word.
inline precise real3 environment_texel(ENV_PARAM uint x, uint y) {
  uint w = ENV_TEXEL(y * uint(ENV_TABLE(RTVK_ENV_WIDTH)) + x);
  uint e = w >> 24u;
  if (e == 0u) return real3(0.0);
  precise real s = rgbe_scale(e);
  return real3(real(w & 255u) * s, real((w >> 8u) & 255u) * s, real((w >> 16u) & 255u) * s);
}

// Whether camera rays that escape see the map (else the scene's sky).
inline bool environment_visible(ENV_ONLY) {
  return ENV_TABLE(RTVK_ENV_VISIBLE) != real(0.0);
}

// The loop trips one environment_sample costs (its two binary searches, at most): what a GPU
// render counts against its loop budget (shaders/shading.glsl).
inline uint environment_sample_trips(ENV_ONLY) {
  return uint(ENV_TABLE(RTVK_ENV_TRIPS));
}

// A world direction in the map's own frame: turned by -rotation about +y.
inline precise real3 environment_local(ENV_PARAM real3 d) {
  precise real c = ENV_TABLE(RTVK_ENV_COS);
  precise real s = ENV_TABLE(RTVK_ENV_SIN);
  return real3(c * d.x - s * d.z, d.y, s * d.x + c * d.z);
}

// A direction in the map's frame back in the world: turned by +rotation about +y (rotation 90
// takes the image's center from +x to -z).
inline precise real3 environment_world(ENV_PARAM real3 l) {
  precise real c = ENV_TABLE(RTVK_ENV_COS);
  precise real s = ENV_TABLE(RTVK_ENV_SIN);
  return real3(c * l.x + s * l.z, l.y, c * l.z - s * l.x);
}

// The texel a unit direction in the map's frame falls in (Blender's equirectangular convention,
// rtvk's y up: the image's center looks along +x, u = 0 and 1 along -x, u = 3/4 along +z; the
// top row looks up, +y). x across the row, y the row from the top.
inline uvec2 environment_texel_of(ENV_PARAM real3 l) {
  uint width = uint(ENV_TABLE(RTVK_ENV_WIDTH));
  uint height = uint(ENV_TABLE(RTVK_ENV_HEIGHT));
  precise real u = real(0.5) + atan2(l.z, l.x) * (real(0.5) * environment_inv_pi);
  precise real t = acos(min(max(l.y, real(-1.0)), real(1.0))) * environment_inv_pi;
  precise real across = max(u, real(0.0)) * real(width);
  precise real down = max(t, real(0.0)) * real(height);
  uint x = min(uint(across), width - 1u);
  uint y = min(uint(down), height - 1u);
  return uvec2(x, y);
}

// What a ray along `direction` (any length but 0) sees: its texel's radiance times the strength.
inline precise real3 environment_radiance(ENV_PARAM real3 direction) {
  uvec2 at = environment_texel_of(ENV environment_local(ENV unit_vector(direction)));
  return ENV_TABLE(RTVK_ENV_STRENGTH) * environment_texel(ENV at.x, at.y);
}

// Where row y's conditional CDF starts in the table.
inline uint environment_row_base(ENV_PARAM uint y) {
  uint width = uint(ENV_TABLE(RTVK_ENV_WIDTH));
  uint height = uint(ENV_TABLE(RTVK_ENV_HEIGHT));
  return uint(RTVK_ENV_HEADER) + height + 1u + y * (width + 1u);
}

// The sampler's solid-angle density in texel (x, y) along the unit direction l of the map's
// frame: the texel's probability over its area in (u, t), 1 / (2 pi^2 sin(theta)) per unit of
// u and t. 0 at the poles (sin(theta) = 0: no solid angle).
inline precise real environment_pdf_at(ENV_PARAM uint x, uint y, real3 l) {
  precise real sin_theta = sqrt(l.x * l.x + l.z * l.z);
  if (!(sin_theta > real(0.0))) return real(0.0);
  uint m = uint(RTVK_ENV_HEADER) + y;
  uint r = environment_row_base(ENV y) + x;
  precise real row = ENV_TABLE(m + 1u) - ENV_TABLE(m);
  precise real column = ENV_TABLE(r + 1u) - ENV_TABLE(r);
  precise real uv = row * ENV_TABLE(RTVK_ENV_HEIGHT) * column * ENV_TABLE(RTVK_ENV_WIDTH);
  return uv / (real(2.0) * environment_pi * environment_pi * sin_theta);
}

// The density environment_sample draws `direction` (any length but 0) with, per steradian.
inline precise real environment_pdf(ENV_PARAM real3 direction) {
  precise real3 l = environment_local(ENV unit_vector(direction));
  uvec2 at = environment_texel_of(ENV l);
  return environment_pdf_at(ENV at.x, at.y, l);
}

// The step of the CDF of n steps at `base` (n + 1 entries, 0 to 1) that u in [0, 1) falls in:
// the largest i with cdf[i] <= u. A step of width 0 is never chosen. At most ceil(log2(n)) trips.
inline uint environment_search(ENV_PARAM uint base, uint n, real u) {
  uint lo = 0u;
  uint hi = n;  // cdf[lo] <= u < cdf[hi]
  while (hi - lo > 1u) {
    uint mid = (lo + hi) / 2u;
    if (ENV_TABLE(base + mid) <= u)
      lo = mid;
    else
      hi = mid;
  }
  return lo;
}

// Where u falls inside step i of the CDF at `base`, 0 to 1.
inline precise real environment_step_fraction(ENV_PARAM uint base, uint i, real u) {
  precise real lo = ENV_TABLE(base + i);
  precise real hi = ENV_TABLE(base + i + 1u);
  return min(max((u - lo) / (hi - lo), real(0.0)), environment_below_one);
}

// A direction toward the map drawn from two uniform numbers in [0, 1): a row by the marginal CDF
// (u.y), a texel in it by its conditional CDF (u.x), a point uniform in the texel's (u, t); with
// the radiance along it and its density (environment_pdf's), at infinity, not a delta.
inline light_sample environment_sample(ENV_PARAM real2 u) {
  uint width = uint(ENV_TABLE(RTVK_ENV_WIDTH));
  uint height = uint(ENV_TABLE(RTVK_ENV_HEIGHT));
  precise real uy = min(u.y, environment_below_one);
  precise real ux = min(u.x, environment_below_one);
  uint marginal = uint(RTVK_ENV_HEADER);
  uint y = environment_search(ENV marginal, height, uy);
  uint row = environment_row_base(ENV y);
  uint x = environment_search(ENV row, width, ux);
  precise real s = (real(x) + environment_step_fraction(ENV row, x, ux)) / real(width);
  precise real t = (real(y) + environment_step_fraction(ENV marginal, y, uy)) / real(height);
  precise real phi = (real(2.0) * s - real(1.0)) * environment_pi;  // atan2(z, x)
  precise real theta = t * environment_pi;                          // from +y
  precise real sin_theta = sin(theta);
  precise real3 l = real3(sin_theta * cos(phi), cos(theta), sin_theta * sin(phi));
  light_sample ls;
  ls.wi = environment_world(ENV l);
  ls.distance = light_at_infinity;
  ls.radiance = ENV_TABLE(RTVK_ENV_STRENGTH) * environment_texel(ENV x, y);
  ls.pdf = environment_pdf_at(ENV x, y, l);
  ls.delta = false;
  return ls;
}

RTVK_KERNELS_END

#endif  // RTVK_ENVIRONMENT_H
