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

// The part of random_bits that depends on the sample only, shared by all its numbers.
constexpr std::uint32_t sample_key(std::uint32_t seed, std::uint32_t pixel,
                                   std::uint32_t sample_index) {
  return hash32(hash32(hash32(seed ^ 0x9e3779b9u) ^ pixel) ^ sample_index);
}

constexpr std::uint32_t random_bits(std::uint32_t seed, std::uint32_t pixel,
                                    std::uint32_t sample_index, std::uint32_t bounce,
                                    std::uint32_t dim) {
  return hash32(sample_key(seed, pixel, sample_index) ^ ((bounce << 4) | dim));
}

// The top 24 bits as a float in [0, 1): exact in float and in double alike.
constexpr float bits_to_unit(std::uint32_t bits) {
  return float(bits >> 8) * (1.0f / 16777216.0f);
}

constexpr float random_float(std::uint32_t seed, std::uint32_t pixel, std::uint32_t sample_index,
                             std::uint32_t bounce, std::uint32_t dim) {
  return bits_to_unit(random_bits(seed, pixel, sample_index, bounce, dim));
}

// The random numbers of one pixel sample at one bounce. The sample's key is hashed once, when
// the stream is made: every number then costs one hash, not four (the same numbers).
class random_stream {
 public:
  constexpr random_stream() : random_stream(0, 0, 0, 0) {}
  constexpr random_stream(std::uint32_t seed, std::uint32_t pixel, std::uint32_t sample_index,
                          std::uint32_t bounce)
      : key_(sample_key(seed, pixel, sample_index)), bounce_(bounce) {}

  double operator()(std::uint32_t dim) const {
    return bits_to_unit(hash32(key_ ^ ((bounce_ << 4) | dim)));
  }
  random_stream at_bounce(std::uint32_t b) const { return random_stream(key_, b); }

 private:
  constexpr random_stream(std::uint32_t key, std::uint32_t bounce) : key_(key), bounce_(bounce) {}
  std::uint32_t key_;     // sample_key(seed, pixel y * width + x from the top, sample index)
  std::uint32_t bounce_;  // 0 for the camera ray, k for the k-th scatter
};

inline constexpr double pi = 3.1415926535897932385;

// (cos, sin) of the angle 2 pi b, b in [0, 1), without libm's sincos (a tenth of the CPU's time
// when it was called for every bounce): b picks the nearest quarter turn q, and the rest, an
// angle of at most pi/4, goes through Taylor polynomials to theta^15 and theta^16, whose error
// (< 1e-16) is below double's rounding. shaders/random.glsl computes the same polynomials in
// float, so both backends turn the same numbers into the same directions.
inline glm::dvec2 turn_cos_sin(double b) {
  const int q = int(4.0 * b + 0.5);  // the nearest quarter turn, 0 .. 4
  const double theta = (4.0 * b - double(q)) * (pi / 2.0);
  const double t2 = theta * theta;
  const double t4 = t2 * t2;
  const double t8 = t4 * t4;
  // Estrin's scheme: independent pairs, a short chain of dependent multiplies.
  const double s = theta * ((1.0 + t2 * (-1.0 / 6.0)) + t4 * (1.0 / 120.0 + t2 * (-1.0 / 5040.0)) +
                            t8 * ((1.0 / 362880.0 + t2 * (-1.0 / 39916800.0)) +
                                  t4 * (1.0 / 6227020800.0 + t2 * (-1.0 / 1307674368000.0))));
  const double c = (1.0 + t2 * (-1.0 / 2.0)) + t4 * (1.0 / 24.0 + t2 * (-1.0 / 720.0)) +
                   t8 * ((1.0 / 40320.0 + t2 * (-1.0 / 3628800.0)) +
                         t4 * (1.0 / 479001600.0 + t2 * (-1.0 / 87178291200.0))) +
                   t8 * t8 * (1.0 / 20922789888000.0);
  // Turned by q quarter turns without a branch (a random quadrant would mispredict it most
  // times): the 0-or-1 factors keep the values exact.
  const double odd = double(q & 1), even = 1.0 - odd, half_turn = 1.0 - double(q & 2);
  return glm::dvec2(half_turn * (c * even - s * odd), half_turn * (s * even + c * odd));
}

// Uniform on the unit sphere's surface, from two uniform numbers (no rejection loop, so both
// backends draw the same count of numbers).
inline vec3 random_unit_vector(double a, double b) {
  const double z = 1.0 - 2.0 * a;
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  const glm::dvec2 phi = turn_cos_sin(b);
  return vec3(r * phi.x, r * phi.y, z);
}

// Uniform inside the unit sphere: the radius's cube has to be uniform.
inline vec3 random_in_unit_sphere(double a, double b, double c) {
  return std::cbrt(c) * random_unit_vector(a, b);
}

// Uniform inside the unit disk (z = 0 plane).
inline glm::dvec2 random_in_unit_disk(double a, double b) {
  return std::sqrt(a) * turn_cos_sin(b);
}

}  // namespace rtvk
