#pragma once
// Scenes lit by environment maps (issue 46), for the CPU's tests and the GPU's.
#include <string>
#include <vector>

#include "light_sources.h"
#include "scene.h"
#include "scene_file.h"

namespace rtvk::test {

// docs/scenes/sky-sun.hdr (scripts/make-test-environment.py): a sky gradient and a
// sun of radiance ~5000, 3 degrees in radius, along (0.4096, 0.5736, 0.7094).
inline const std::string sky_sun_file =
    std::string(RTVK_TEST_DATA) + "/../../docs/scenes/sky-sun.hdr";

// A map of w x h texels of one radiance, with texel (bx, by) `bright` where given.
inline environment_map uniform_map(int w, int h, float value, int bx = -1, int by = -1,
                                   float bright = 0) {
  std::vector<float> rgb(std::size_t(w * h) * 3, value);
  if (bx >= 0)
    for (int c = 0; c < 3; ++c) rgb[std::size_t(3 * (by * w + bx) + c)] = bright;
  environment_map e;
  e.file = "test";
  e.image = environment_from_rgb(w, h, rgb, "test");
  return e;
}

inline environment_map sky_sun_map(double rotation = 0) {
  environment_map e;
  e.file = sky_sun_file;
  e.image = load_environment_image(sky_sun_file, "test");
  e.rotation = rotation;
  return e;
}

// A white furnace: a white Lambertian sphere inside a uniform environment of `radiance`, plain
// sampling: L everywhere (a bounce off a convex sphere escapes at once into the map).
inline scene furnace_scene(float radiance) {
  scene s;
  s.name = "environment furnace";
  main_camera(s).pose.lookfrom = point3(0, 0, 3);
  main_camera(s).pose.lookat = point3(0, 0, 0);
  main_camera(s).pose.vfov = 30;
  s.render.width = 24;
  s.render.aspect = 1;
  s.render.spp = 4;
  s.render.max_depth = 8;
  s.render.sampling = sampling_mode::plain;
  s.materials = {{"white", {material_type::lambertian, color(1), 0, 1.5}}};
  s.spheres = {sphere(point3(0, 0, 0), 1, 0)};
  s.environment = uniform_map(16, 8, radiance);
  return s;
}

// Three spheres (diffuse, metal, glass) on a diffuse floor under the test map, turned 30 degrees
// and at strength 0.5: the sun casts their shadows.
inline scene sunlit_scene() {
  scene s;
  s.name = "sunlit";
  main_camera(s).pose.lookfrom = point3(0, 1.2, 4.5);
  main_camera(s).pose.lookat = point3(0, 0.4, 0);
  main_camera(s).pose.vfov = 35;
  s.render.width = 48;
  s.render.aspect = 1.5;
  s.render.spp = 16;
  s.render.max_depth = 6;
  s.materials = {{"floor", {material_type::lambertian, color(0.5), 0, 1.5}},
                 {"red", {material_type::lambertian, color(0.7, 0.2, 0.2), 0, 1.5}},
                 {"metal", {material_type::metal, color(0.8), 0.1, 1.5}},
                 {"glass", {material_type::dielectric, color(1), 0, 1.5}}};
  s.spheres = {sphere(point3(0, -1000, 0), 1000, 0), sphere(point3(-1.1, 0.5, 0), 0.5, 1),
               sphere(point3(0, 0.5, 0), 0.5, 2), sphere(point3(1.1, 0.5, 0), 0.5, 3)};
  s.environment = sky_sun_map(30);
  s.environment->strength = 0.5;
  return s;
}

}  // namespace rtvk::test
