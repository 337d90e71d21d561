// Mirrors host/base/random.h: the same 32-bit integer arithmetic, so both backends draw the same
// random numbers for the same (seed, pixel, sample, bounce, dimension).
#ifndef RTVK_RANDOM_GLSL
#define RTVK_RANDOM_GLSL
#include "ray.glsl"

const uint dim_jitter_u = 0u;
const uint dim_jitter_v = 1u;
const uint dim_lens_a = 2u;
const uint dim_lens_b = 3u;
const uint dim_direction_a = 0u;
const uint dim_direction_b = 1u;
const uint dim_fuzz_radius = 2u;
const uint dim_choice = 3u;

uint hash32(uint x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

uint random_bits(uint seed, uint pixel, uint sample_index, uint bounce, uint dim) {
  uint h = hash32(seed ^ 0x9e3779b9u);
  h = hash32(h ^ pixel);
  h = hash32(h ^ sample_index);
  return hash32(h ^ ((bounce << 4) | dim));
}

precise float random_float(uint seed, uint pixel, uint sample_index, uint bounce, uint dim) {
  return float(random_bits(seed, pixel, sample_index, bounce, dim) >> 8) * (1.0 / 16777216.0);
}

// The random numbers of one pixel sample at one bounce (host: random_stream).
struct random_stream {
  uint seed;
  uint pixel;
  uint sample_index;
  uint bounce;
};

precise float rnd(random_stream s, uint dim) {
  return random_float(s.seed, s.pixel, s.sample_index, s.bounce, dim);
}

random_stream at_bounce(random_stream s, uint b) {
  return random_stream(s.seed, s.pixel, s.sample_index, b);
}

// turn_cos_sin of host/base/random.h: (cos, sin) of 2 pi b from the same polynomials.
precise vec2 turn_cos_sin(float b) {
  int q = int(4.0 * b + 0.5);
  precise float theta = (4.0 * b - float(q)) * (pi / 2.0);
  precise float t2 = theta * theta;
  precise float t4 = t2 * t2;
  precise float t8 = t4 * t4;
  // Estrin's scheme: independent pairs, a short chain of dependent multiplies.
  precise float s = theta * ((1.0 + t2 * (-1.0 / 6.0)) + t4 * (1.0 / 120.0 + t2 * (-1.0 / 5040.0)) +
                      t8 * ((1.0 / 362880.0 + t2 * (-1.0 / 39916800.0)) +
                            t4 * (1.0 / 6227020800.0 + t2 * (-1.0 / 1307674368000.0))));
  precise float c = (1.0 + t2 * (-1.0 / 2.0)) + t4 * (1.0 / 24.0 + t2 * (-1.0 / 720.0)) +
             t8 * ((1.0 / 40320.0 + t2 * (-1.0 / 3628800.0)) +
                   t4 * (1.0 / 479001600.0 + t2 * (-1.0 / 87178291200.0))) +
             t8 * t8 * (1.0 / 20922789888000.0);
  // Turned by q quarter turns without a branch (a random quadrant would mispredict it most
  // times): the 0-or-1 factors keep the values exact.
  precise float odd = float(q & 1), even = 1.0 - odd, half_turn = 1.0 - float(q & 2);
  return vec2(half_turn * (c * even - s * odd), half_turn * (s * even + c * odd));
}

precise vec3 random_unit_vector(float a, float b) {
  precise float z = 1.0 - 2.0 * a;
  precise float r = sqrt(max(0.0, 1.0 - z * z));
  precise vec2 phi = turn_cos_sin(b);
  return vec3(r * phi.x, r * phi.y, z);
}

precise vec3 random_in_unit_sphere(float a, float b, float c) {
  return pow(c, 1.0 / 3.0) * random_unit_vector(a, b);
}

precise vec2 random_in_unit_disk(float a, float b) {
  return sqrt(a) * turn_cos_sin(b);
}

#endif
