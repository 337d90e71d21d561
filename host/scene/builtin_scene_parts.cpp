// What the built-in scenes share: the books' materials, render settings, cameras and the
// Cornell box.
#include <algorithm>
#include <cmath>
#include <memory>

#include "builtin_scene_parts.h"
#include "random.h"

namespace rtvk::builtin {

material lambertian(color albedo) {
  return {material_type::lambertian, albedo, 0, 1.5};
}
material metal(color albedo, double fuzz) {
  return {material_type::metal, albedo, fuzz, 1.5};
}
material dielectric(double ir) {
  return {material_type::dielectric, color(1), 0, ir};
}

render_settings book_render(int width, double aspect, int spp) {
  render_settings r;
  r.width = width;
  r.aspect = aspect;
  r.spp = spp;
  r.max_depth = 50;
  r.gamma = 2;
  r.jitter = true;
  return r;
}

material lamp(color emit) {
  return {material_type::diffuse_light, emit, 0, 1.5};
}
material isotropic(color albedo) {
  return {material_type::isotropic, albedo, 0, 1.5};
}
// A lambertian colored by texture t, which is appended to the scene.
material textured(scene& s, texture t) {
  material m = lambertian(color(1));
  m.texture = int(s.textures.size());
  s.textures.push_back(std::move(t));
  return m;
}
texture noise_texture(double scale) {
  texture t;
  t.type = texture_type::noise;
  t.scale = scale;
  return t;
}
int add_material(scene& s, const std::string& name, material m) {
  s.materials.push_back({name, m});
  return int(s.materials.size() - 1);
}
// The book's rotate_y by `degrees`, then translate by `offset`.
transform turned_and_moved(double degrees, const vec3& offset) {
  return make_transform(vec3(1), vec3(0, 1, 0), degrees, offset);
}
// The second book's cameras: the lookfrom, lookat and field of view given, no lens.
void next_week_camera(scene& s, const point3& from, const point3& at, double vfov) {
  camera_pose& c = main_camera(s).pose;
  c.lookfrom = from;
  c.lookat = at;
  c.vup = vec3(0, 1, 0);
  c.vfov = vfov;
  c.aperture = 0;
}

// The second book's early scenes' set-up: 400 pixels wide at 16:9, 100 samples, the camera at
// `from` looking at `at` (vfov 20), a constant background.
scene next_week_scene(const std::string& name, const point3& from, const point3& at,
                      const color& background) {
  scene s;
  s.name = name;
  next_week_camera(s, from, at, 20);
  s.render = book_render(400, 16.0 / 9.0, 100);
  s.sky.horizon = s.sky.zenith = background;
  return s;
}

cornell_colors cornell_setup(scene& s, int spp) {
  next_week_camera(s, point3(278, 278, -800), point3(278, 278, 0), 40);
  s.render = book_render(600, 1.0, spp);
  s.sky.horizon = s.sky.zenith = color(0, 0, 0);
  return {add_material(s, "red", lambertian(color(.65, .05, .05))),
          add_material(s, "white", lambertian(color(.73, .73, .73))),
          add_material(s, "green", lambertian(color(.12, .45, .15)))};
}

// The Cornell box's walls (green right, red left, white floor, ceiling and back), its lamp of
// `light` at (Q, u, v), and the book's camera. Returns the white material.
int add_cornell_walls(scene& s, color light, const point3& Q, const vec3& u, const vec3& v,
                      bool smoke) {
  const auto [red, white, green] = cornell_setup(s, 200);
  const int lit = add_material(s, "light", lamp(light));
  s.quads.push_back({point3(555, 0, 0), vec3(0, 555, 0), vec3(0, 0, 555), green});
  s.quads.push_back({point3(0, 0, 0), vec3(0, 555, 0), vec3(0, 0, 555), red});
  if (smoke) {  // cornell_smoke lists the lamp and the walls in this order, with these corners
    s.quads.push_back({Q, u, v, lit});
    s.quads.push_back({point3(0, 555, 0), vec3(555, 0, 0), vec3(0, 0, 555), white});
    s.quads.push_back({point3(0, 0, 0), vec3(555, 0, 0), vec3(0, 0, 555), white});
  } else {
    s.quads.push_back({Q, u, v, lit});
    s.quads.push_back({point3(0, 0, 0), vec3(555, 0, 0), vec3(0, 0, 555), white});
    s.quads.push_back({point3(555, 555, 555), vec3(-555, 0, 0), vec3(0, 0, -555), white});
  }
  s.quads.push_back({point3(0, 0, 555), vec3(555, 0, 0), vec3(0, 555, 0), white});
  return white;
}

}  // namespace rtvk::builtin
