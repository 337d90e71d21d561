#pragma once
// Small scenes of PBR materials (material_type::pbr) for the render-level tests of both backends
// (tests/cpu/test_pbr_render.cpp, tests/gpu/test_gpu_pbr.cpp): each small enough for lavapipe.
#include <cmath>

#include "framebuffer.h"
#include "scene.h"

namespace rtvk::test {

// A PBR material of this base color, metallic and roughness (the rest glTF's defaults).
inline material pbr_of(color base, double metallic, double roughness) {
  material m;
  m.type = material_type::pbr;
  m.albedo = base;
  m.pbr.metallic = metallic;
  m.pbr.roughness = roughness;
  return m;
}

// The white furnace at render level: one sphere of material `m` filling most of the view, under
// a uniform sky of 1. An energy-conserving BSDF of white base color returns every path with 1
// (a sphere is convex: a reflected path leaves it; a transmitted one leaves it in the end).
inline scene pbr_furnace(const material& m) {
  scene s;
  s.name = "pbr furnace";
  main_camera(s).pose.lookfrom = point3(0, 0, 3);
  main_camera(s).pose.lookat = point3(0, 0, 0);
  main_camera(s).pose.vfov = 40;
  s.render.width = 24;
  s.render.aspect = 1;
  s.render.spp = 16;
  s.render.jitter = true;
  s.render.max_depth = 32;
  s.sky = {color(1), color(1)};
  s.materials = {{"white", m}};
  s.spheres = {sphere(point3(0, 0, 0), 1, 0)};
  return s;
}

// The mean of the center half (in each axis) of an image: pbr_furnace's sphere covers it.
inline color center_mean(const framebuffer& fb) {
  color sum(0);
  int n = 0;
  for (int y = fb.height() / 4; y < 3 * fb.height() / 4; ++y)
    for (int x = fb.width() / 4; x < 3 * fb.width() / 4; ++x, ++n) sum += fb.at(x, y);
  return sum / double(n);
}

// What the furnace's mean may be off 1 by: Monte Carlo noise (16 spp, 144 pixels: a standard
// error under 0.5% for the model's spread of path weights) and the model's own energy error
// (multiple-scattering compensation is not exact). The stand-in Lambertian gives exactly 1.
constexpr double pbr_furnace_tolerance = 0.03;

// Beer-Lambert (KHR_materials_volume): the camera at the center of a sphere of radius `radius`
// whose PBR material has a volume (thickness 1) attenuating to `attenuation` over `distance`,
// and emits white on its inside; black base color and one bounce, so that every pixel is the
// emission seen through `radius` of the volume: attenuation^(radius / distance), analytically.
inline scene pbr_absorbing_sphere(color attenuation, double distance, double radius) {
  scene s;
  s.name = "pbr volume";
  main_camera(s).pose.lookfrom = point3(0, 0, 0);
  main_camera(s).pose.lookat = point3(0, 0, -1);
  main_camera(s).pose.vfov = 60;
  s.render.width = 16;
  s.render.aspect = 1;
  s.render.spp = 2;
  s.render.jitter = true;
  s.render.max_depth = 1;
  material m = pbr_of(color(0), 0, 0);
  m.emission = color(1);
  m.pbr.transmission = 1;
  m.pbr.thickness = 1;
  m.pbr.attenuation_color = attenuation;
  m.pbr.attenuation_distance = distance;
  s.materials = {{"absorbing", m}};
  s.spheres = {sphere(point3(0, 0, 0), radius, 0)};
  return s;
}

inline color beer_lambert(color attenuation, double distance, double radius) {
  const double x = radius / distance;
  return color(std::pow(attenuation.r, x), std::pow(attenuation.g, x), std::pow(attenuation.b, x));
}

// PBR spheres of several kinds (metal, rough dielectric, textured metal and roughness, clearcoat,
// transmission with a volume, sheen) on a lambertian floor, lit by the sky and a lamp quad (so
// that the lights' mixture runs: sampling is automatic), at max_depth 8.
inline scene pbr_gallery() {
  scene s;
  s.name = "pbr gallery";
  main_camera(s).pose.lookfrom = point3(0, 1.2, 4);
  main_camera(s).pose.lookat = point3(0, 0.4, 0);
  main_camera(s).pose.vfov = 40;
  s.render.width = 48;
  s.render.aspect = 1.5;
  s.render.spp = 8;
  s.render.jitter = true;
  s.render.max_depth = 8;
  s.sky = {color(0.6, 0.7, 0.8), color(0.3, 0.4, 0.7)};
  texture checker;
  checker.type = texture_type::checker;
  checker.scale = 0.2;
  checker.even = color(1, 0.2, 1);
  checker.odd = color(1, 1, 0.1);
  s.textures = {checker};
  material textured = pbr_of(color(0.9, 0.6, 0.3), 1, 1);
  textured.pbr.metallic_roughness_texture = 0;
  material coated = pbr_of(color(0.6, 0.05, 0.05), 0.3, 0.5);
  coated.pbr.clearcoat = 1;
  coated.pbr.clearcoat_roughness = 0.1;
  material glass = pbr_of(color(1), 0, 0.1);
  glass.pbr.transmission = 1;
  glass.pbr.thickness = 1;
  glass.pbr.attenuation_color = color(0.8, 0.4, 0.3);
  glass.pbr.attenuation_distance = 0.5;
  material velvet = pbr_of(color(0.2, 0.1, 0.4), 0, 0.8);
  velvet.pbr.sheen_color = color(0.9, 0.7, 1);
  velvet.pbr.sheen_roughness = 0.5;
  material lamp;
  lamp.type = material_type::diffuse_light;
  lamp.albedo = color(4);
  s.materials = {{"floor", {material_type::lambertian, color(0.6), 0, 1.5}},
                 {"metal", pbr_of(color(0.95, 0.8, 0.5), 1, 0.2)},
                 {"plastic", pbr_of(color(0.1, 0.4, 0.8), 0, 0.4)},
                 {"textured", textured},
                 {"coated", coated},
                 {"glass", glass},
                 {"velvet", velvet},
                 {"lamp", lamp}};
  s.spheres = {sphere(point3(0, -100, 0), 100, 0),     sphere(point3(-1.5, 0.4, 0), 0.4, 1),
               sphere(point3(-0.5, 0.4, 0.3), 0.4, 2), sphere(point3(0.5, 0.4, 0.3), 0.4, 3),
               sphere(point3(1.5, 0.4, 0), 0.4, 4),    sphere(point3(-0.6, 0.3, 1.2), 0.3, 5),
               sphere(point3(0.6, 0.3, 1.2), 0.3, 6)};
  s.quads = {{point3(-1, 2.5, -1), vec3(2, 0, 0), vec3(0, 0, 2), 7}};
  return s;
}

}  // namespace rtvk::test
