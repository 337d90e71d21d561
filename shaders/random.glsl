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

precise vec3 random_unit_vector(float a, float b) {
  precise float z = 1.0 - 2.0 * a;
  precise float r = sqrt(max(0.0, 1.0 - z * z));
  precise float phi = 2.0 * pi * b;
  return vec3(r * cos(phi), r * sin(phi), z);
}

precise vec3 random_in_unit_sphere(float a, float b, float c) {
  return pow(c, 1.0 / 3.0) * random_unit_vector(a, b);
}

precise vec2 random_in_unit_disk(float a, float b) {
  precise float r = sqrt(a);
  precise float theta = 2.0 * pi * b;
  return vec2(r * cos(theta), r * sin(theta));
}

#endif
