// The language the shared kernels are written in: the common subset of GLSL 450 and C++20, with
// the few words that differ bridged here. Every header of shaders/shared/ that holds rendering
// math includes this first, and compiles twice: into the shaders (glslangValidator) and into the
// C++ backends, so that "the GPU mirrors get_ray" is "the GPU compiles get_ray".
//
// Kernels write
//   real, real2..4      the compilation's scalar and vectors: GLSL float; C++ RTVK_REAL (double
//                       for the CPU reference; float for the tests that hold the C++ against
//                       the GPU operation for operation). One typedef per compilation.
//   float, uint, bool   the same in both languages, whatever `real` is.
//   real(2.0) * v       a literal next to a vector: C++'s float vectors take no double scalar.
//   OUT(T), INOUT(T)    GLSL's out and inout parameters (C++: references).
//   precise             GLSL: no reassociation and no fused multiply-adds; C++ is built with
//                       -ffp-contract=off and never reassociates, so the word is empty there.
//   inline              C++: header functions; GLSL: empty.
// and call only the GLSL built-ins listed below, which C++ finds in std:: and glm (atan2 is C's
// name, which GLSL gets here).
#ifndef RTVK_KERNEL_LANG_H
#define RTVK_KERNEL_LANG_H

#ifdef __cplusplus
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include <glm/common.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <limits>

// A translation unit picks its scalar before the first kernel header, e.g. the float one of the
// tests: #define RTVK_REAL float, #define RTVK_KERNEL_NAMESPACE rtvk::f32.
#ifndef RTVK_REAL
#define RTVK_REAL double
#endif
#ifndef RTVK_KERNEL_NAMESPACE
#define RTVK_KERNEL_NAMESPACE rtvk
#endif
#define RTVK_KERNELS_BEGIN namespace RTVK_KERNEL_NAMESPACE {
#define RTVK_KERNELS_END }
#define OUT(T) T&
#define INOUT(T) T&
#define precise

namespace RTVK_KERNEL_NAMESPACE {
using real = RTVK_REAL;
using real2 = glm::vec<2, real>;
using real3 = glm::vec<3, real>;
using real4 = glm::vec<4, real>;
// The compilation's machine epsilon: iterations that converge stop within a few of it.
inline constexpr real real_epsilon = std::numeric_limits<real>::epsilon();
using uint = std::uint32_t;
using uvec2 = glm::uvec2;
using uvec3 = glm::uvec3;
// The GLSL built-ins the kernels call.
using glm::floor;
using glm::max;
using glm::min;
using std::abs;
using std::acos;
using std::asin;
using std::atan2;
using std::cos;
using std::floor;
using std::log;
using std::log2;
using std::pow;
using std::sin;
using std::sqrt;
// Where one source cannot serve: GLSL has no cube root. pow(x, 1/3) there, cbrt here; the two
// differ in the last bits, so the probes compare them with a bound.
inline real cube_root(real x) {
  return std::cbrt(x);
}
// Not NaN and not infinite. The GLSL body tests the bits: Vulkan lets a driver assume that no
// float is NaN or infinite (and fold isnan, isinf and comparisons with them) unless a shader
// declares SignedZeroInfNanPreserve, so a guard must not depend on float semantics there.
inline bool is_finite(real x) {
  return std::isfinite(x);
}
inline uint floatBitsToUint(float x) {  // GLSL's built-in
  uint u;
  std::memcpy(&u, &x, sizeof u);
  return u;
}
inline uint bitfieldReverse(uint x) {  // GLSL's built-in: bit i moves to bit 31 - i
  x = ((x >> 1u) & 0x55555555u) | ((x & 0x55555555u) << 1u);  // within pairs of bits,
  x = ((x >> 2u) & 0x33333333u) | ((x & 0x33333333u) << 2u);  // then nibbles,
  x = ((x >> 4u) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4u);  // then bytes;
  return __builtin_bswap32(x);                                // the bytes' order (one instruction)
}
}  // namespace RTVK_KERNEL_NAMESPACE

#else  // GLSL

#define RTVK_KERNELS_BEGIN
#define RTVK_KERNELS_END
#define OUT(T) out T
#define INOUT(T) inout T
#define inline
#define real float
#define real2 vec2
#define real3 vec3
#define real4 vec4
#define real_epsilon 1.1920929e-7
precise float cube_root(float x) {
  return pow(x, 1.0 / 3.0);
}
float atan2(float y, float x) {  // C's name for GLSL's two-argument atan
  return atan(y, x);
}
bool is_finite(float x) {
  return (floatBitsToUint(x) & 0x7f800000u) != 0x7f800000u;  // the exponent is not all ones
}

#endif

#endif  // RTVK_KERNEL_LANG_H
