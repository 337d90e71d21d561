#pragma once
#include <optional>
#include <string>

#include <glm/mat3x3.hpp>

#include "vec3.h"

namespace rtvk {

// An affine placement of an object: p -> linear * p + offset. Scene files build it from a scale,
// a rotation about any axis and a translation, applied in that order (the book's rotate_y and
// translate are the special cases). Quads and triangles stay exact under it (a parallelogram
// maps to a parallelogram): instances are placed by transforming their vertices.
struct transform {
  glm::dmat3 linear{1.0};  // scale and rotation, column-major
  vec3 offset{0.0};        // translation, scene units

  // The identity leaves every coordinate exactly as it was (-0 stays -0, +0 stays +0), so that a
  // dumped scene reads back unchanged.
  point3 apply_point(const point3& p) const { return is_identity() ? p : linear * p + offset; }
  vec3 apply_vector(const vec3& v) const { return is_identity() ? v : linear * v; }
  // A surface normal's image, unit length: the inverse transpose carries normals.
  vec3 apply_normal(const vec3& n) const;
  double determinant() const;
  bool is_identity() const { return linear == glm::dmat3(1.0) && offset == vec3(0.0); }
  // Whether the linear part keeps shapes (a rotation times one scale, possibly mirrored): what a
  // sphere can be placed by. Returns that scale.
  std::optional<double> uniform_scale() const;
};

// scale, then rotation by `degrees` about `axis` (right-handed), then translation.
transform make_transform(const vec3& scale, const vec3& axis, double degrees, const vec3& offset);

// The composition: `outer` after `inner`.
transform compose(const transform& outer, const transform& inner);

// Why t cannot place anything (a non-finite entry, or a determinant that is zero or too small
// to invert), or nothing when it can.
std::optional<std::string> degenerate(const transform& t);

}  // namespace rtvk
