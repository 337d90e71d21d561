#pragma once
// Meshes for the tangent tests: a flat grid whose uv are an affine map of its plane, so that the
// tangent (dp/du made unit) and the handedness are known in closed form.
#include <array>
#include <cmath>

#include "scene.h"

namespace rtvk::test {

// The plane's frame: p = origin + u * U + v * V (U and V not perpendicular, nor unit).
struct affine_uv {
  point3 origin{0.5, -0.25, -3};
  vec3 U{1.5, 0.25, 0.5};
  vec3 V{0.5, 1.25, -0.25};
  vec3 normal() const { return glm::normalize(glm::cross(U, V)); }
};

// A pbr material with a normal map (texture index 0: the generator only asks whether it has one).
inline material normal_mapped_pbr() {
  material m;
  m.type = material_type::pbr;
  m.pbr.normal_texture = 0;
  return m;
}

// n x n squares of two triangles each over u, v in [0, 2], into s's own triangles (material 0).
// Where `mirror`, the squares with u > 1 take their uv mirrored about u = 1 (u -> 2 - u): the
// right half's texture is the left's turned over, as a symmetric model's is. Each corner keeps
// its position, the plane's normal and its uv; the corners on the seam u = 1 are shared by both
// halves with the same uv.
inline void add_uv_grid(scene& s, const affine_uv& f, int n, bool mirror) {
  const auto at = [&](int i, int j) { return glm::dvec2(2.0 * i / n, 2.0 * j / n); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const std::array<glm::dvec2, 4> q = {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
      for (const std::array<int, 3> tri : {std::array<int, 3>{0, 1, 2}, {0, 2, 3}}) {
        triangle t;
        triangle_shading sh;
        for (std::size_t k = 0; k < 3; ++k) {
          const glm::dvec2 g = q[std::size_t(tri[k])];
          t.p[k] = f.origin + g.x * f.U + g.y * f.V;
          sh.normal[k] = f.normal();
          sh.uv[k] = mirror && i >= n / 2 ? glm::dvec2(2 - g.x, g.y) : g;
        }
        sh.has_uv = true;
        t.material = 0;
        t.shading = std::int32_t(s.shading.size());
        s.shading.push_back(sh);
        s.triangles.push_back(t);
      }
    }
}

}  // namespace rtvk::test
