#include "transform.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/matrix.hpp>

#include "format.h"

namespace rtvk {

vec3 transform::apply_normal(const vec3& n) const {
  return glm::normalize(glm::inverseTranspose(linear) * n);
}

double transform::determinant() const {
  return glm::determinant(linear);
}

std::optional<double> transform::uniform_scale() const {
  // linear^T linear = s^2 I exactly for a scaled rotation; allow rounding of its entries.
  const glm::dmat3 g = glm::transpose(linear) * linear;
  const double s2 = (g[0][0] + g[1][1] + g[2][2]) / 3;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (std::abs(g[i][j] - (i == j ? s2 : 0.0)) > 1e-9 * s2) return std::nullopt;
  return std::sqrt(s2);
}

transform make_transform(const vec3& scale, const vec3& axis, double degrees, const vec3& offset) {
  transform t;
  glm::dmat3 rotation(1.0);
  if (degrees != 0) {
    // Rodrigues' formula, so that quarter turns about an axis come out with exact zeros.
    const vec3 k = glm::normalize(axis);
    const double turns = degrees / 360.0;
    const double r = turns - std::floor(turns);
    double c = std::cos(2 * M_PI * r), s = std::sin(2 * M_PI * r);
    if (r == 0.25) c = 0, s = 1;
    if (r == 0.5) c = -1, s = 0;
    if (r == 0.75) c = 0, s = -1;
    const glm::dmat3 K(0, k.z, -k.y, -k.z, 0, k.x, k.y, -k.x, 0);  // columns: cross(k, .)
    rotation = glm::dmat3(1.0) + s * K + (1 - c) * (K * K);
  }
  t.linear = rotation * glm::dmat3(scale.x, 0, 0, 0, scale.y, 0, 0, 0, scale.z);
  t.offset = offset;
  return t;
}

transform compose(const transform& outer, const transform& inner) {
  return {outer.linear * inner.linear, outer.linear * inner.offset + outer.offset};
}

std::optional<std::string> degenerate(const transform& t) {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(t.offset[i])) return "the translation is not finite";
    for (int j = 0; j < 3; ++j)
      if (!std::isfinite(t.linear[i][j])) return "the matrix is not finite";
  }
  double largest = 0;
  for (int i = 0; i < 3; ++i) largest = std::max(largest, glm::length(t.linear[i]));
  const double det = t.determinant();
  // Relative to the largest column cubed: a flattened placement, whatever the units.
  if (!(std::abs(det) > 1e-12 * largest * largest * largest))
    return "it flattens space (determinant " + format_number(det) + ")";
  return std::nullopt;
}

}  // namespace rtvk
