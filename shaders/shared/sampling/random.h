// The one random number generator of both backends, counter-based: the numbers for (seed, pixel,
// sample, bounce, dimension) are a pure function of those integers, computed with the same 32-bit
// integer arithmetic in C++ and GLSL, so both draw identical numbers. And the samplers that turn
// them into directions and lens points.
#ifndef RTVK_RANDOM_H
#define RTVK_RANDOM_H
#include "kernel_lang.h"
#include "sobol.h"

RTVK_KERNELS_BEGIN

// Dimensions within one bounce; at most 16 (4 bits).
const uint dim_jitter_u = 0u;     // bounce 0: pixel jitter
const uint dim_jitter_v = 1u;     //
const uint dim_lens_a = 2u;       // bounce 0: lens sample
const uint dim_lens_b = 3u;       //
const uint dim_time = 4u;         // bounce 0: the instant in the shutter interval
const uint dim_direction_a = 0u;  // bounce >= 1: scatter direction
const uint dim_direction_b = 1u;  //
const uint dim_fuzz_radius = 2u;  // bounce >= 1: metal fuzz
const uint dim_choice = 3u;       // bounce >= 1: reflect or refract
// dim 4, bounce >= 1: a medium's scattering distance (medium.h)
const uint dim_mixture = 5u;     // bounce >= 1: the lights' density or the material's (pdf.h)
const uint dim_light_pick = 6u;  // bounce >= 1: which light
const uint dim_light_a = 7u;     // bounce >= 1: the point or direction on it
const uint dim_light_b = 8u;     //
// bounce >= 1: whether a blended surface lets the ray through (ray_color.h's path_passes); its
// bounce field holds the surfaces passed before, above bit 16, so each draws its own number
const uint dim_alpha = 9u;

// A 32-bit integer hash with good avalanche ("lowbias32", Chris Wellons).
inline uint hash32(uint x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

// The part of sample_key that depends on the pixel only: what low-discrepancy numbers
// (sobol.h) scramble a pixel's samples by.
inline uint pixel_key(uint seed, uint pixel) {
  return hash32(hash32(seed ^ 0x9e3779b9u) ^ pixel);
}

// The part of random_bits that depends on the sample only, shared by all its numbers.
inline uint sample_key(uint seed, uint pixel, uint sample_index) {
  return hash32(pixel_key(seed, pixel) ^ sample_index);
}

inline uint random_bits(uint seed, uint pixel, uint sample_index, uint bounce, uint dim) {
  return hash32(sample_key(seed, pixel, sample_index) ^ ((bounce << 4) | dim));
}

// The top 24 bits as a float in [0, 1): exact in float and in double alike.
inline precise float bits_to_unit(uint bits) {
  return float(bits >> 8) * (1.0f / 16777216.0f);
}

inline precise float random_float(uint seed, uint pixel, uint sample_index, uint bounce, uint dim) {
  return bits_to_unit(random_bits(seed, pixel, sample_index, bounce, dim));
}

// The random numbers of one pixel sample at one bounce. The sample's key is hashed once, when the
// stream is made: every number then costs one hash, not four (the same numbers). rnd reads key
// and bounce only; sobol.h's low-discrepancy numbers need the pixel's key and the raw sample
// index apart (a sample's points are a permutation of one Sobol sequence per pixel), so the
// stream carries them too, and whether its every number is one of those.
struct random_stream {
  uint key;              // sample_key(seed, pixel y * width + x from the top, sample index)
  uint bounce;           // 0 for the camera ray, k for the k-th scatter
  uint pixel_key;        // pixel_key(seed, pixel): key without the sample index
  uint sample_index;     // the sample's index in its pixel
  bool low_discrepancy;  // rnd draws Owen-scrambled Sobol numbers (next-event estimation's paths)
#ifdef __cplusplus
  random_stream() : random_stream(0u, 0u, 0u, 0u, false) {}
  random_stream(uint k, uint b, uint p, uint i, bool ld)
      : key(k), bounce(b), pixel_key(p), sample_index(i), low_discrepancy(ld) {}
#endif
};

// The stream of a pixel sample's camera ray (bounce 0), of hashed numbers (the books' modes).
inline random_stream pixel_sample_stream(uint seed, uint pixel, uint sample_index) {
  uint p = pixel_key(seed, pixel);
  return random_stream(hash32(p ^ sample_index), 0u, p, sample_index, false);
}

// Stream s drawing low-discrepancy numbers in every dimension instead (next-event estimation).
inline random_stream with_low_discrepancy(random_stream s) {
  s.low_discrepancy = true;
  return s;
}

// The seed of a dimension (or of a pair, by its first dimension) of one pixel's samples at one
// bounce: the pixel's key with rnd's counter (bounce << 4 | dim), spread by an odd multiplier
// (one to one) and offset so that no seed is rnd's key of sample 0, hashed once.
inline uint sobol_seed(random_stream s, uint dim) {
  return hash32(s.pixel_key ^ (((s.bounce << 4u) | dim) * 0x9e3779b9u + 0x50b01u));
}

// The sample's index in the pair's copy of the sequence, and the two coordinates' scramble seeds.
inline uint sobol_index(uint sample_index, uint seed) {
  return nested_uniform_scramble(sample_index, seed);
}
inline uint sobol_seed_x(uint seed) {
  return hash32(seed ^ 0xa511e9b3u);
}
inline uint sobol_seed_y(uint seed) {
  return hash32(seed ^ 0x63d83595u);
}

// The 32 bits of dimension `dim`, and of the pair that begins at `dim`: the scrambles of
// sobol_first and sobol_second of sobol_index, written with the reversals that cancel left out
// (nested_uniform_scramble(sobol_first(i), s) = bitfieldReverse(laine_karras_permutation(i, s)),
// and likewise sobol_second's with sobol_pascal(i)): 3 and 4 reversals, not 6 and 8.
inline uint sobol_bits(random_stream s, uint dim) {
  uint seed = sobol_seed(s, dim);
  uint index = sobol_index(s.sample_index, seed);
  return bitfieldReverse(laine_karras_permutation(index, sobol_seed_x(seed)));
}

inline uvec2 sobol_bits2(random_stream s, uint dim) {
  uint seed = sobol_seed(s, dim);
  uint index = sobol_index(s.sample_index, seed);
  return uvec2(bitfieldReverse(laine_karras_permutation(index, sobol_seed_x(seed))),
               bitfieldReverse(laine_karras_permutation(sobol_pascal(index), sobol_seed_y(seed))));
}

// A low-discrepancy number in [0, 1), rounded as rnd's (the top 24 bits).
inline precise real sobol_rnd(random_stream s, uint dim) {
  return real(bits_to_unit(sobol_bits(s, dim)));
}

// The pair of dimensions (dim, dim + 1) as one 2D point: (0, k, 2)-nets over a pixel's samples.
inline precise real2 sobol_rnd2(random_stream s, uint dim) {
  uvec2 b = sobol_bits2(s, dim);
  return real2(real(bits_to_unit(b.x)), real(bits_to_unit(b.y)));
}

// Which dimensions are the second of a pair (sobol_rnd2): the pixel's jitter and a scattered
// direction (0, 1), the lens point or a metal's fuzz with glass's choice (2, 3), the point on a
// light (7, 8), a PBR lobe's direction (11, 12). A stream's numbers in a pair's two dimensions
// are then one 2D point of a (0, 2)-net, as pixel_spot, scatter.h and nee.h use them.
const uint sobol_pair_seconds = (1u << 1u) | (1u << 3u) | (1u << 8u) | (1u << 12u);

// Dimension `dim` of stream s as a low-discrepancy number: its pair's second coordinate or its
// own (a first's number is sobol_rnd's, the first coordinate of its pair).
inline precise float sobol_dimension(random_stream s, uint dim) {
  if (((sobol_pair_seconds >> dim) & 1u) != 0u)
    return bits_to_unit(sobol_bits2(s, dim - 1u).y);
  return bits_to_unit(sobol_bits(s, dim));
}

// The uniform number of dimension `dim` in [0, 1): hashed from the stream's key and counter, or
// the low-discrepancy one where the stream asks for those.
inline precise float rnd(random_stream s, uint dim) {
  if (s.low_discrepancy) return sobol_dimension(s, dim);
  return bits_to_unit(hash32(s.key ^ ((s.bounce << 4) | dim)));
}

inline random_stream at_bounce(random_stream s, uint b) {
  return random_stream(s.key, b, s.pixel_key, s.sample_index, s.low_discrepancy);
}

// (cos, sin) of the angle 2 pi b, b in [0, 1), without libm's sincos (a tenth of the CPU's time
// when it was called for every bounce): b picks the nearest quarter turn q, and the rest, an
// angle of at most pi/4, goes through Taylor polynomials to theta^15 and theta^16, whose error
// (< 1e-16) is below double's rounding.
inline precise real2 turn_cos_sin(real b) {
  int q = int(real(4.0) * b + real(0.5));  // the nearest quarter turn, 0 .. 4
  precise real theta = (real(4.0) * b - real(q)) * real(3.1415926535897932385 / 2.0);
  precise real t2 = theta * theta;
  precise real t4 = t2 * t2;
  precise real t8 = t4 * t4;
  // Estrin's scheme: independent pairs, a short chain of dependent multiplies.
  precise real s =
      theta *
      ((real(1.0) + t2 * real(-1.0 / 6.0)) + t4 * (real(1.0 / 120.0) + t2 * real(-1.0 / 5040.0)) +
       t8 * ((real(1.0 / 362880.0) + t2 * real(-1.0 / 39916800.0)) +
             t4 * (real(1.0 / 6227020800.0) + t2 * real(-1.0 / 1307674368000.0))));
  precise real c = (real(1.0) + t2 * real(-1.0 / 2.0)) +
                   t4 * (real(1.0 / 24.0) + t2 * real(-1.0 / 720.0)) +
                   t8 * ((real(1.0 / 40320.0) + t2 * real(-1.0 / 3628800.0)) +
                         t4 * (real(1.0 / 479001600.0) + t2 * real(-1.0 / 87178291200.0))) +
                   t8 * t8 * real(1.0 / 20922789888000.0);
  // Turned by q quarter turns without a branch (a random quadrant would mispredict it most
  // times): the 0-or-1 factors keep the values exact.
  precise real odd = real(q & 1);
  precise real even = real(1.0) - odd;
  precise real half_turn = real(1.0) - real(q & 2);
  return real2(half_turn * (c * even - s * odd), half_turn * (s * even + c * odd));
}

// Uniform on the unit sphere's surface, from two uniform numbers (no rejection loop, so both
// backends draw the same count of numbers).
inline precise real3 random_unit_vector(real a, real b) {
  precise real z = real(1.0) - real(2.0) * a;
  precise real r = sqrt(max(real(0.0), real(1.0) - z * z));
  precise real2 phi = turn_cos_sin(b);
  return real3(r * phi.x, r * phi.y, z);
}

// Uniform inside the unit sphere: the radius's cube has to be uniform.
inline precise real3 random_in_unit_sphere(real a, real b, real c) {
  return cube_root(c) * random_unit_vector(a, b);
}

// Uniform inside the unit disk (z = 0 plane).
inline precise real2 random_in_unit_disk(real a, real b) {
  return sqrt(a) * turn_cos_sin(b);
}

RTVK_KERNELS_END

#endif  // RTVK_RANDOM_H
