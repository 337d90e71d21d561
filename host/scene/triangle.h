#pragma once
#include <array>
#include <cstdint>

#include <glm/vec2.hpp>

#include "vec3.h"

namespace rtvk {

// A triangle of the scene: one face of a mesh, or one given alone. Plain data; both backends hit
// it with the shared, watertight hit_triangle (shaders/shared/hit_triangle.h).
struct triangle {
  std::array<point3, 3> p{};  // vertices, scene units; counter-clockwise seen from the front
  int material = 0;           // index into the scene's materials
  std::int32_t shading = -1;  // index into the scene's triangle_shading; -1: flat, no uv
};

// What a mesh gives its vertices beyond positions: normals for smooth shading and texture
// coordinates (kept for textures: nothing reads them yet).
struct triangle_shading {
  std::array<vec3, 3> normal{};    // unit vertex normals, or all zero: flat
  std::array<glm::dvec2, 3> uv{};  // texture coordinates (0, 0 where the mesh has none)
  bool has_normals() const { return normal[0] != vec3(0); }
};

}  // namespace rtvk
