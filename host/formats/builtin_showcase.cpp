// The showcase scene and the test environment it stands under (builtin_showcase.h).
#include "builtin_showcase.h"

#include <algorithm>
#include <cmath>

#include "mesh_file.h"
#include "showcase_glb.h"  // generated: docs/scenes/showcase.glb's bytes (CMakeLists.txt)

namespace rtvk {
namespace {

// scripts/make-test-environment.py's constants: its sun and sky (linear RGB radiance).
constexpr double sun_elevation_degrees = 35;
constexpr double sun_azimuth_degrees = 60;  // from +x toward +z, about +y
constexpr double sun_radius_degrees = 3;
const color sun_radiance{5000, 4800, 4500};
const color horizon{0.9, 0.95, 1.0};
const color zenith{0.25, 0.45, 1.0};
const color ground{0.2, 0.18, 0.15};

double radians(double degrees) {
  return degrees * 3.14159265358979323846 / 180;
}

// What the map shows along unit direction d: the sun within its radius of sky_sun_direction, else
// the sky's blend by height (the ground below the horizon).
color sky_sun_radiance(const vec3& d) {
  if (glm::dot(d, sky_sun_direction()) >= std::cos(radians(sun_radius_degrees)))
    return sun_radiance;
  if (d.y < 0) return ground;
  const double up = std::min(d.y, 1.0);
  return (1 - up) * horizon + up * zenith;
}

}  // namespace

vec3 sky_sun_direction() {
  const double e = radians(sun_elevation_degrees), a = radians(sun_azimuth_degrees);
  return {std::cos(e) * std::cos(a), std::sin(e), std::cos(e) * std::sin(a)};
}

std::shared_ptr<const environment_image> sky_sun_image() {
  constexpr int width = 256, height = 128;
  constexpr double pi = 3.14159265358979323846;
  std::vector<float> rgb;
  rgb.reserve(std::size_t(3) * width * height);
  // Texel (i, j) from the top left looks along phi = (2u - 1) pi, theta = t pi at its center
  // (docs/lighting.md's convention, the script's texel_directions).
  for (int j = 0; j < height; ++j) {
    const double theta = (j + 0.5) / height * pi;
    for (int i = 0; i < width; ++i) {
      const double phi = (2 * ((i + 0.5) / width) - 1) * pi;
      const vec3 d(std::sin(theta) * std::cos(phi), std::cos(theta),
                   std::sin(theta) * std::sin(phi));
      const color c = sky_sun_radiance(d);
      rgb.insert(rgb.end(), {float(c.x), float(c.y), float(c.z)});
    }
  }
  return environment_from_rgb(width, height, rgb, builtin_sky_sun);
}

scene showcase_scene() {
  scene s;
  s.name = "showcase";
  camera_pose& pose = main_camera(s).pose;
  pose.lookfrom = point3(0.5, 1.4, 4.7);
  pose.lookat = point3(0.05, 0.4, 0);
  pose.vfov = 30;
  // A picture, as a mesh file's defaults draw one: sRGB, antialiased, and next-event estimation,
  // which draws the sun's few texels at every diffuse and PBR vertex (plain sampling finds them
  // by chance).
  s.render.width = 640;
  s.render.aspect = 1.6;
  s.render.spp = 64;
  s.render.max_depth = 8;
  s.render.transform = view_transform::standard;
  s.render.jitter = true;
  s.render.sampling = sampling_mode::nee;
  // The sun turned to the camera's upper left (azimuth 60 + 60 degrees from +x toward +z), so
  // that the shadows fall back and to the right, in view. 0.15 keeps the lit ground below white.
  s.environment = environment_map{builtin_sky_sun, sky_sun_image(), -60, 0.15, true};
  s.materials.push_back({"ground", {material_type::lambertian, color(0.4, 0.4, 0.4)}});
  s.quads.push_back({point3(-500, 0, 500), vec3(1000, 0, 0), vec3(0, 0, -1000), 0});
  const std::string glb(reinterpret_cast<const char*>(showcase_glb), sizeof showcase_glb);
  load_mesh_bytes(s, glb, "glb", "builtin:showcase.glb", {}, mesh_placement{});
  return s;
}

std::vector<std::string> format_scene_names() {
  return {"showcase"};
}

}  // namespace rtvk
