#pragma once
#include <array>
#include <cmath>

#include <glm/geometric.hpp>

#include "hit_disk.h"
#include "vec3.h"

namespace rtvk {

// A disk of the scene: the points of the plane through `center` facing `normal` within
// `radius` of the center. Plain data; both backends hit it with the shared hit_disk
// (shaders/shared/hit_disk.h). docs/geometry.md shows it; scene files write
// {"type": "disk", "center": [x, y, z], "normal": [x, y, z], "radius": r, "material": "m"}.
struct disk {
  point3 center{};             // scene units
  vec3 normal{0.0, 1.0, 0.0};  // the front side; any length but zero
  double radius = 1.0;         // scene units, > 0
  int material = 0;            // index into the scene's materials

  // The precomputed plane and axes, in double.
  disk_geometry geometry() const { return make_disk(center, normal, radius); }

  // Corners lo and hi of its bounding box: along axis k the disk reaches
  // radius * sqrt(1 - n_k^2) from its center (n the unit normal).
  std::array<point3, 2> bounds() const {
    const vec3 n = glm::normalize(normal);
    const vec3 reach = radius * glm::sqrt(glm::max(vec3(1.0) - n * n, vec3(0.0)));
    return {center - reach, center + reach};
  }
};

// Whether `normal` has a direction in double and in float: a disk without one has no plane.
inline bool has_direction(const vec3& normal) {
  const double len2 = glm::dot(normal, normal);
  const glm::vec3 nf(normal);
  const float len2f = glm::dot(nf, nf);
  return len2 > 0 && std::isfinite(len2) && len2f > 0 && std::isfinite(len2f);
}

}  // namespace rtvk
