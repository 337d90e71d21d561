#pragma once
// Internal to scene/: the built-in scenes, one file per book (builtin_scenes_weekend.cpp,
// builtin_scenes_next_week.cpp, builtin_scenes_rest_of_life.cpp), and the parts they share
// (builtin_scene_parts.cpp): the books' materials, settings, cameras and Cornell box.
#include <cstdint>
#include <string>

#include "scene.h"

namespace rtvk::builtin {

material lambertian(color albedo);
material metal(color albedo, double fuzz);
material dielectric(double ir);
material lamp(color emit);
material isotropic(color albedo);
// A lambertian colored by texture t, which is appended to the scene.
material textured(scene& s, texture t);
texture noise_texture(double scale);
// Appends a named material; returns its index.
int add_material(scene& s, const std::string& name, material m);
// The book's rotate_y by `degrees`, then translate by `offset`.
transform turned_and_moved(double degrees, const vec3& offset);
// The books' settings: `width` pixels at `aspect`, `spp` samples, 50 bounces, gamma 2, jittered.
render_settings book_render(int width, double aspect, int spp);
// The second book's cameras: the lookfrom, lookat and field of view given, no lens.
void next_week_camera(scene& s, const point3& from, const point3& at, double vfov);
// The second book's early scenes' set-up: 400 pixels wide at 16:9, 100 samples, the camera at
// `from` looking at `at` (vfov 20), a constant background.
scene next_week_scene(const std::string& name, const point3& from, const point3& at,
                      const color& background);

// The Cornell box's camera, its dark background and its walls' three materials, as both books
// set them up.
struct cornell_colors {
  int red, white, green;  // material indices
};
cornell_colors cornell_setup(scene& s, int spp);
// The Cornell box's walls (green right, red left, white floor, ceiling and back), its lamp of
// `light` at (Q, u, v), and the book's camera. Returns the white material.
int add_cornell_walls(scene& s, color light, const point3& Q, const vec3& u, const vec3& v,
                      bool smoke);

// "Ray Tracing in One Weekend" (and the second book's first scene, its cover bouncing).
scene seed_scene();
scene materials_scene();
scene book_final_scene();
scene bouncing_spheres_scene();
scene spheres_scene(std::uint32_t n);
// "Ray Tracing: The Next Week".
scene quads_scene();
scene checkered_spheres_scene();
scene perlin_spheres_scene();
scene simple_light_scene();
scene cornell_box_scene();
scene cornell_smoke_scene();
scene next_week_final_scene();
// "Ray Tracing: The Rest of Your Life".
scene rest_of_life_final_scene();

}  // namespace rtvk::builtin
