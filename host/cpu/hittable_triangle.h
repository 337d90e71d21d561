#pragma once
#include <array>
#include <limits>

#include "hit_triangle.h"
#include "hittable.h"
#include "triangle.h"

namespace rtvk {

// The record of a hit at t on the triangle with vertices p, shaded by `a` (null: flat, uv
// barycentric). The blend's weights are found again by the same test: only the winner of a search
// pays for them.
inline void record_triangle(const std::array<point3, 3>& p, const triangle_attributes* a,
                            uint material, const ray& r, const sheared_ray& s, double t,
                            hit_record& rec) {
  const double inf = std::numeric_limits<double>::infinity();
  double again;
  real3 weights(0);
  const bool found = hit_triangle(p[0], p[1], p[2], r, s, -inf, inf, again, weights);
  const bool smooth = found && a && a->smooth;
  const bool has_uv = a && a->has_uv;
  const vec3 none(0);
  const vec3 shading =
      shading_normal(p[0], p[1], p[2], smooth, smooth ? a->normal[0] : none,
                     smooth ? a->normal[1] : none, smooth ? a->normal[2] : none, weights);
  const glm::dvec2 zero(0);
  const glm::dvec2 uv = triangle_uv(has_uv, has_uv ? a->uv[0] : zero, has_uv ? a->uv[1] : zero,
                                    has_uv ? a->uv[2] : zero, weights);
  record_triangle_hit(p[0], p[1], p[2], shading, uv, material, r, t, rec);
  if (a && a->has_color) rec.color = blend_colors(a->color[0], a->color[1], a->color[2], weights);
  if (a && a->has_uv1) rec.uv1 = triangle_uv(true, a->uv1[0], a->uv1[1], a->uv1[2], weights);
  if (a && a->has_tangent)
    rec.tangent = blend_tangents(a->tangent[0], a->tangent[1], a->tangent[2], weights, rec);
}

// A scene triangle as a hittable, for the lesson's hittable_list.
class hittable_triangle final : public hittable {
 public:
  // `shading`: the triangle's shading entry, or null (flat, no uv).
  hittable_triangle(const triangle& t, const triangle_shading* shading)
      : p_(t.p), has_attributes_(shading != nullptr), material_(uint(t.material)) {
    if (shading) attributes_ = attributes_of(*shading);
  }

  bool hit(const ray& r, double t_min, double t_max, hit_record& rec) const override {
    const sheared_ray s = shear_ray(r);
    double t;
    real3 weights;
    if (!hit_triangle(p_[0], p_[1], p_[2], r, s, t_min, t_max, t, weights)) return false;
    record_triangle(p_, has_attributes_ ? &attributes_ : nullptr, material_, r, s, t, rec);
    return true;
  }

 private:
  std::array<point3, 3> p_;         // vertices, scene units
  triangle_attributes attributes_;  // normals and uv, when has_attributes_
  bool has_attributes_;             // has a shading entry
  uint material_;                   // index into the scene's materials
};

}  // namespace rtvk
