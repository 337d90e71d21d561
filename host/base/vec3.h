#pragma once
// The lesson's vector vocabulary, spelled with GLM's double-precision vectors. The ray and the
// helpers every kernel uses (dot3, divide, unit_vector) are the shared kernels' (ray.h), which the
// CPU compiles with double.
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace rtvk {

using vec3 = glm::dvec3;    // a direction or offset, scene units
using point3 = glm::dvec3;  // a position, scene units
using color = glm::dvec3;   // linear RGB, each channel nominally in [0, 1]

}  // namespace rtvk

#include "ray.h"
