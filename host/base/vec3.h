#pragma once
// The lesson's vector vocabulary, spelled with GLM's double-precision vectors.
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace rtvk {

using vec3 = glm::dvec3;    // a direction or offset, scene units
using point3 = glm::dvec3;  // a position, scene units
using color = glm::dvec3;   // linear RGB, each channel nominally in [0, 1]

// The lesson divides by multiplying with the reciprocal ((1/t) * v); doing the
// same keeps the reference image bit-identical to the lesson's.
inline vec3 divide(const vec3& v, double t) {
  return (1.0 / t) * v;
}

inline vec3 unit_vector(const vec3& v) {
  return divide(v, glm::length(v));
}

}  // namespace rtvk
