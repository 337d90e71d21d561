#pragma once
#include <array>
#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "vec3.h"

namespace rtvk {

// A triangle of the scene: one face of a mesh, or one given alone. Plain data; both backends hit
// it with the shared, watertight hit_triangle (shaders/shared/hit_triangle.h).
struct triangle {
  std::array<point3, 3> p{};  // vertices, scene units; counter-clockwise seen from the front
  int material = 0;           // index into the scene's materials
  std::int32_t shading = -1;  // index into the scene's triangle_shading; -1: flat, no uv

  // Corners lo and hi of its box: the vertices' extremes.
  std::array<point3, 2> bounds() const {
    return {glm::min(glm::min(p[0], p[1]), p[2]), glm::max(glm::max(p[0], p[1]), p[2])};
  }
};

// Whether the triangle with vertices p has an area to hit and a normal to shade with, in double
// (the CPU) and in float (the GPU, from the vertices rounded): a zero-area triangle can be hit
// only through rounding, and its normal would be 0 / 0.
inline bool has_area(const std::array<point3, 3>& p) {
  const vec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
  const glm::vec3 a(p[0]), b(p[1]), c(p[2]);
  const glm::vec3 nf = glm::cross(b - a, c - a);
  const double len2 = glm::dot(n, n);
  const float len2f = glm::dot(nf, nf);
  return len2 > 0 && std::isfinite(len2) && len2f > 0 && std::isfinite(len2f);
}

// What a mesh gives its vertices beyond positions: normals for smooth shading and texture
// coordinates (image textures read them).
struct triangle_shading {
  std::array<vec3, 3> normal{};      // unit vertex normals, or all zero: flat
  std::array<glm::dvec2, 3> uv{};    // texture coordinates (0, 0 where the mesh has none)
  bool has_uv = false;               // uv came from the mesh (else a hit's uv is barycentric)
  std::array<glm::vec4, 3> color{};  // vertex colors (glTF COLOR_0, OBJ "v x y z r g b"): linear
                                     // RGBA, multiplying the material's color and alpha
  bool has_color = false;            // color came from the mesh
  // A second set of texture coordinates, which the material's emission texture reads where the
  // triangle has it (glTF's emissiveTexture on another TEXCOORD_n or transform than the base
  // color's, that transform baked in); where it has not, the emission texture reads uv.
  std::array<glm::dvec2, 3> uv1{};
  bool has_uv1 = false;  // uv1 came from the mesh
  // Vertex tangents for normal maps (glTF's TANGENT convention): xyz the unit tangent along +u,
  // w the handedness, +1 or -1, so that the bitangent (along +v) is cross(normal, xyz) * w. Read
  // from the mesh or generated (tangent_frames.h); only with normals and uv.
  std::array<glm::vec4, 3> tangent{};
  bool has_tangent = false;  // tangent is set
  bool has_normals() const { return normal[0] != vec3(0); }
};

// A triangle's shading as both backends' searches keep it: normals normalized once.
struct triangle_attributes {
  std::array<vec3, 3> normal{};         // unit vertex normals, when smooth
  std::array<glm::dvec2, 3> uv{};       // texture coordinates, when has_uv
  std::array<glm::dvec4, 3> color{};    // vertex colors (linear RGBA), when has_color
  std::array<glm::dvec2, 3> uv1{};      // the emission texture's coordinates, when has_uv1
  std::array<glm::dvec4, 3> tangent{};  // unit vertex tangents and handedness, when has_tangent
  bool smooth = false;                  // shaded by the blended normals, else flat
  bool has_uv = false;                  // uv given by the mesh
  bool has_color = false;               // vertex colors given by the mesh
  bool has_uv1 = false;                 // a second set given by the mesh
  bool has_tangent = false;             // tangents given (only where smooth)
};
inline triangle_attributes attributes_of(const triangle_shading& sh) {
  triangle_attributes a;
  a.smooth = sh.has_normals();
  if (a.smooth)
    for (std::size_t k = 0; k < 3; ++k) a.normal[k] = glm::normalize(sh.normal[k]);
  a.has_uv = sh.has_uv;
  a.uv = sh.uv;
  a.has_color = sh.has_color;
  for (std::size_t k = 0; k < 3; ++k) a.color[k] = glm::dvec4(sh.color[k]);
  a.has_uv1 = sh.has_uv1;
  a.uv1 = sh.uv1;
  a.has_tangent = a.smooth && sh.has_tangent;
  if (a.has_tangent)
    for (std::size_t k = 0; k < 3; ++k) {
      const vec3 t = glm::normalize(vec3(sh.tangent[k]));
      a.tangent[k] = glm::dvec4(t, sh.tangent[k].w < 0 ? -1.0 : 1.0);
    }
  return a;
}

}  // namespace rtvk
