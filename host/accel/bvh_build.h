#pragma once
// The BVH builder's own types (bvh.cpp, bvh_prims.cpp): boxes in float SIMD registers, the
// objects as prims. Internal to accel/: nothing outside includes it.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "bvh.h"
#include "uninitialized_allocator.h"

namespace rtvk::bvh_build {

// Four floats in one SIMD register (GCC and Clang vector extension): x, y, z and an unused w.
using float4 = float __attribute__((vector_size(16)));
inline float4 min4(float4 a, float4 b) {
  return a < b ? a : b;
}
inline float4 max4(float4 a, float4 b) {
  return a > b ? a : b;
}
inline float4 splat4(float v) {
  return float4{v, v, v, v};
}

// A box in float, rounded outward from the objects' double boxes, so unions stay exact and
// conservative.
struct fbox {
  float4 lo = splat4(std::numeric_limits<float>::infinity());
  float4 hi = splat4(-std::numeric_limits<float>::infinity());
  void grow(float4 l, float4 h) {
    lo = min4(lo, l);
    hi = max4(hi, h);
  }
  void grow(const fbox& b) { grow(b.lo, b.hi); }
  void grow(float4 p) { grow(p, p); }
  double half_area() const {
    const double x = double(hi[0]) - lo[0], y = double(hi[1]) - lo[1], z = double(hi[2]) - lo[2];
    return x < 0 ? 0 : x * y + y * z + z * x;
  }
};

// One object as the builder sees it.
struct prim {
  float4 lo, hi;         // the object's box, rounded outward to float (w: 0)
  std::uint32_t object;  // its scene index (primitive_spans: spheres, quads, triangles)
  float4 centroid() const { return (lo + hi) * 0.5f; }
};

using prim_vector = uninitialized_vector<prim>;

// What the builder knows of a range of prims before splitting it.
struct range_info {
  fbox bounds;     // of the spheres' boxes
  fbox centroids;  // of their centroids
};

constexpr int bins = 16;
// Ranges larger than this build their two halves as parallel tasks, and larger than
// `parallel_bins` bin their prims in parallel chunks.
constexpr std::size_t parallel_subtree = 4096;
constexpr std::size_t parallel_bins = 1 << 16;
// Ranges of at most this many prims try every split point instead of binning.
constexpr std::size_t small_range = 12;

// The float next to x towards -infinity / +infinity (std::nextafter without the libm call).
inline float next_down(float x) {
  if (!(x > -INFINITY) || x != x) return x;
  if (x == 0) return -std::numeric_limits<float>::denorm_min();
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(x);
  return std::bit_cast<float>(x > 0 ? bits - 1 : bits + 1);
}
inline float next_up(float x) {
  return -next_down(-x);
}

// The objects as prims, their boxes rounded outward to float, and the whole range's info.
range_info make_prims(const primitive_spans& objects, time_span motion, prim_vector& prims);

}  // namespace rtvk::bvh_build
