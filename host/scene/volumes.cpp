#include "volumes.h"

#include <stdexcept>

#include <glm/matrix.hpp>

namespace rtvk {

medium_geometry geometry_of(const medium& m, std::uint32_t index) {
  medium_geometry g;
  glm::dmat3 inverse(1.0);
  vec3 offset(0.0);
  if (m.shape == boundary_shape::box && !m.placement.is_identity()) {
    if (degenerate(m.placement)) throw std::invalid_argument("a medium's placement is degenerate");
    inverse = glm::inverse(m.placement.linear);
    offset = -(inverse * m.placement.offset);
  }
  // Rows of the inverse (glm is column-major: row r is (m[0][r], m[1][r], m[2][r])).
  g.to_local_x = vec3(inverse[0][0], inverse[1][0], inverse[2][0]);
  g.to_local_y = vec3(inverse[0][1], inverse[1][1], inverse[2][1]);
  g.to_local_z = vec3(inverse[0][2], inverse[1][2], inverse[2][2]);
  g.to_local_offset = offset;
  g.shape = std::uint32_t(m.shape);
  g.lo = m.shape == boundary_shape::sphere ? m.center : m.lo;
  g.hi = m.shape == boundary_shape::sphere ? vec3(m.radius, 0, 0) : m.hi;
  g.neg_inv_density = -1.0 / m.density;
  g.material = std::uint32_t(m.material);
  g.index = index;
  return g;
}

std::string shape_name(boundary_shape s) {
  return s == boundary_shape::box ? "box" : "sphere";
}

}  // namespace rtvk
