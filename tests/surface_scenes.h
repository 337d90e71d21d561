#pragma once
// Small scenes for the surface features beyond the books (material.h: emission, alpha, culling;
// triangle_shading: vertex colors), whose images have known answers: a camera at the origin
// looking down -z (90 degrees, square) at a front quad at z = -1 over a back quad at z = -2, under
// a black sky. Flat materials draw their color unlit and end the path, so each pixel is exactly
// the color of the surface that counts.
#include <memory>

#include "scene.h"

namespace rtvk::test {

// The front quad (covering the view twice over, its front toward the camera unless `flipped`)
// in material 0, the back one in material 1.
inline scene surface_scene(const material& front, const material& back, bool flipped = false) {
  scene s;
  s.name = "surface";
  s.sky = {color(0), color(0)};
  s.materials = {{"front", front}, {"back", back}};
  s.render.width = 16;
  s.render.aspect = 1;
  s.render.spp = 4;
  s.render.max_depth = 4;
  const vec3 u(4, 0, 0), v(0, 4, 0);
  if (flipped)
    s.quads.push_back({point3(-2, -2, -1), v, u, 0});
  else
    s.quads.push_back({point3(-2, -2, -1), u, v, 0});
  s.quads.push_back({point3(-4, -4, -2), vec3(8, 0, 0), vec3(0, 8, 0), 1});
  return s;
}

inline material flat_material(const color& c) {
  material m;
  m.type = material_type::flat;
  m.albedo = c;
  return m;
}

// An image texture of one row: its texels' RGBA8 (red lowest, alpha highest).
inline texture row_texture(std::vector<std::uint32_t> texels) {
  texture t;
  t.type = texture_type::image;
  auto image = std::make_shared<texel_image>();
  image->width = int(texels.size());
  image->height = 1;
  image->texels = std::move(texels);
  t.image = image;
  t.file = "row";
  return t;
}

// Two triangles covering the view at z = -1 (x and y in [-1, 1]), flat white, with vertex colors:
// red at (-1, -1), green at (1, -1), blue at (1, 1), white at (-1, 1), alpha 1.
inline scene vertex_color_scene() {
  scene s = surface_scene(flat_material(color(1)), flat_material(color(0)));
  s.quads.clear();
  const point3 a(-1, -1, -1), b(1, -1, -1), c(1, 1, -1), d(-1, 1, -1);
  const glm::vec4 red(1, 0, 0, 1), green(0, 1, 0, 1), blue(0, 0, 1, 1), white(1, 1, 1, 1);
  triangle_shading first, second;
  first.color = {red, green, blue};
  second.color = {red, blue, white};
  first.has_color = second.has_color = true;
  s.shading = {first, second};
  s.triangles.push_back({{a, b, c}, 0, 0});
  s.triangles.push_back({{a, c, d}, 0, 1});
  return s;
}

// The vertex colors' color at (x, y) of vertex_color_scene's plane: bilinear in effect, blended
// by the triangle (x >= y: red, green, blue; else red, blue, white) it falls in.
inline color vertex_color_at(double x, double y) {
  const double s = (x + 1) / 2, t = (y + 1) / 2;  // in [0, 1]
  if (s >= t) return (1 - s) * color(1, 0, 0) + (s - t) * color(0, 1, 0) + t * color(0, 0, 1);
  return (1 - t) * color(1, 0, 0) + s * color(0, 0, 1) + (t - s) * color(1, 1, 1);
}

// Two triangles covering the view at z = -1 (x and y in [-1, 1]), flat, their color and their
// emission (1) both from one image of two texels, red then green: the color reads the first
// texture coordinates, which put every point on the red texel (u in [0.05, 0.45]); the emission
// reads the second set, on the green texel (u in [0.55, 0.95]), where a triangle has it. The first
// triangle (x >= y) has it and shows red + green; the second has none, its emission reading the
// first set, and shows 2 * red.
inline scene second_uv_scene() {
  scene s = surface_scene(flat_material(color(0)), flat_material(color(0)));
  s.quads.clear();
  s.textures.push_back(row_texture({0xff0000ffu, 0xff00ff00u}));
  s.materials[0].m.texture = 0;
  s.materials[0].m.emission = color(1);
  s.materials[0].m.emission_texture = 0;
  const point3 a(-1, -1, -1), b(1, -1, -1), c(1, 1, -1), d(-1, 1, -1);
  const auto u = [](double lo, double hi, const point3& p) {  // x = -1..1 to u = lo..hi
    return glm::dvec2(lo + (hi - lo) * (p.x + 1) / 2, 0.5);
  };
  triangle_shading first, second;
  first.uv = {u(0.05, 0.45, a), u(0.05, 0.45, b), u(0.05, 0.45, c)};
  first.uv1 = {u(0.55, 0.95, a), u(0.55, 0.95, b), u(0.55, 0.95, c)};
  first.has_uv = first.has_uv1 = true;
  second.uv = {u(0.05, 0.45, a), u(0.05, 0.45, c), u(0.05, 0.45, d)};
  second.has_uv = true;
  s.shading = {first, second};
  s.triangles.push_back({{a, b, c}, 0, 0});
  s.triangles.push_back({{a, c, d}, 0, 1});
  return s;
}

}  // namespace rtvk::test
