#pragma once
#include <array>
#include <limits>

#include "hit_triangle.h"
#include "hittable.h"
#include "triangle.h"

namespace rtvk {

// The record of a hit at t on the triangle with vertices p, shaded smooth by the vertex normals
// `normals` (null: flat). The blend's weights are found again by the same test: only the winner
// of a search pays for them.
inline void record_triangle(const std::array<point3, 3>& p, const std::array<vec3, 3>* normals,
                            uint material, const ray& r, const sheared_ray& s, double t,
                            hit_record& rec) {
  real3 weights(0);
  if (normals) {
    const double inf = std::numeric_limits<double>::infinity();
    double again;
    if (!hit_triangle(p[0], p[1], p[2], r, s, -inf, inf, again, weights)) normals = nullptr;
  }
  const vec3 none(0);
  const vec3 shading =
      shading_normal(p[0], p[1], p[2], normals != nullptr, normals ? (*normals)[0] : none,
                     normals ? (*normals)[1] : none, normals ? (*normals)[2] : none, weights);
  record_triangle_hit(p[0], p[1], p[2], shading, material, r, t, rec);
}

// A scene triangle as a hittable, for the lesson's hittable_list.
class hittable_triangle final : public hittable {
 public:
  // `normals`: the triangle's vertex normals when it is shaded smooth, else null.
  hittable_triangle(const triangle& t, const std::array<vec3, 3>* normals)
      : p_(t.p), smooth_(normals != nullptr), material_(uint(t.material)) {
    if (normals)
      for (std::size_t k = 0; k < 3; ++k) normals_[k] = glm::normalize((*normals)[k]);
  }

  bool hit(const ray& r, double t_min, double t_max, hit_record& rec) const override {
    const sheared_ray s = shear_ray(r);
    double t;
    real3 weights;
    if (!hit_triangle(p_[0], p_[1], p_[2], r, s, t_min, t_max, t, weights)) return false;
    record_triangle(p_, smooth_ ? &normals_ : nullptr, material_, r, s, t, rec);
    return true;
  }

 private:
  std::array<point3, 3> p_;        // vertices, scene units
  std::array<vec3, 3> normals_{};  // vertex normals, when smooth_
  bool smooth_;                    // shaded by normals_
  uint material_;                  // index into the scene's materials
};

}  // namespace rtvk
