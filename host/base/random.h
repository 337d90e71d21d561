#pragma once
// The one random number generator of both backends, counter-based: the numbers for
// (seed, pixel, sample, bounce, dimension) are a pure function of those integers. The GLSL copy in
// shaders/random.glsl does the same 32-bit integer arithmetic, so both draw identical numbers.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/vec2.hpp>

#include "vec3.h"

namespace rtvk {

// A 32-bit integer hash with good avalanche ("lowbias32", Chris Wellons).
constexpr std::uint32_t hash32(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

// Dimensions within one bounce; at most 16 (4 bits).
enum random_dimension : std::uint32_t {
  dim_jitter_u = 0,  // bounce 0: pixel jitter
  dim_jitter_v = 1,
  dim_lens_a = 2,  // bounce 0: lens sample
  dim_lens_b = 3,
  dim_direction_a = 0,  // bounce >= 1: scatter direction
  dim_direction_b = 1,
  dim_fuzz_radius = 2,  // bounce >= 1: metal fuzz
  dim_choice = 3,       // bounce >= 1: reflect or refract
};

constexpr std::uint32_t random_bits(std::uint32_t seed, std::uint32_t pixel,
                                    std::uint32_t sample_index, std::uint32_t bounce,
                                    std::uint32_t dim) {
  std::uint32_t h = hash32(seed ^ 0x9e3779b9u);
  h = hash32(h ^ pixel);
  h = hash32(h ^ sample_index);
  return hash32(h ^ ((bounce << 4) | dim));
}

// The top 24 bits as a float in [0, 1): exact in float and in double alike.
constexpr float random_float(std::uint32_t seed, std::uint32_t pixel, std::uint32_t sample_index,
                             std::uint32_t bounce, std::uint32_t dim) {
  return float(random_bits(seed, pixel, sample_index, bounce, dim) >> 8) * (1.0f / 16777216.0f);
}

// The random numbers of one pixel sample at one bounce.
struct random_stream {
  std::uint32_t seed = 0;          // the render's --seed
  std::uint32_t pixel = 0;         // y * image width + x, y from the top of the full image
  std::uint32_t sample_index = 0;  // sample index within the pixel
  std::uint32_t bounce = 0;        // 0 for the camera ray, k for the k-th scatter

  double operator()(std::uint32_t dim) const {
    return random_float(seed, pixel, sample_index, bounce, dim);
  }
  random_stream at_bounce(std::uint32_t b) const { return {seed, pixel, sample_index, b}; }
};

inline constexpr double pi = 3.1415926535897932385;

// Uniform on the unit sphere's surface, from two uniform numbers (no rejection loop, so both
// backends draw the same count of numbers).
inline vec3 random_unit_vector(double a, double b) {
  const double z = 1.0 - 2.0 * a;
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  const double phi = 2.0 * pi * b;
  return vec3(r * std::cos(phi), r * std::sin(phi), z);
}

// Uniform inside the unit sphere.
inline vec3 random_in_unit_sphere(double a, double b, double c) {
  return std::pow(c, 1.0 / 3.0) * random_unit_vector(a, b);
}

// Uniform inside the unit disk (z = 0 plane).
inline glm::dvec2 random_in_unit_disk(double a, double b) {
  const double r = std::sqrt(a);
  const double theta = 2.0 * pi * b;
  return {r * std::cos(theta), r * std::sin(theta)};
}

}  // namespace rtvk
