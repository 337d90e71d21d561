#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "camera.h"
#include "hittable_list.h"
#include "material.h"
#include "render_settings.h"
#include "sphere.h"

namespace rtvk {

struct named_material {
  std::string name;  // how spheres refer to it in scene files
  material m;        // its optics
};

// What to render, independent of the backend: the CPU builds a hittable_list from it, the GPU
// packs the same spheres and materials into storage buffers.
struct scene {
  std::string name;                       // built-in name or the file it came from
  camera_pose camera;                     // where the camera stands; the lesson's by default
  render_settings render;                 // default image size, samples, depth, ...
  std::vector<named_material> materials;  // spheres index into this
  std::vector<sphere> spheres;            // every object, in the order hits are tested
};

hittable_list make_world(const scene& s);
std::vector<material> scene_materials(const scene& s);

// Throws usage_error when a sphere names a material that does not exist or has a radius that is
// not finite and > 0, naming the sphere.
void check_scene(const scene& s);

// The built-in scene of that name; throws usage_error naming the choices when there is none.
scene builtin_scene(std::string_view name);
std::vector<std::string> builtin_scene_names();

}  // namespace rtvk
