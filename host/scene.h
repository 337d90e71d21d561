#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "hittable_list.h"
#include "sphere.h"

namespace rtvk {

// What to render, independent of the backend: the CPU builds a hittable_list from it, the GPU
// packs the same spheres into a storage buffer.
struct scene {
  std::string name;             // built-in name or file it came from
  std::vector<sphere> spheres;  // every object, in the order hits are tested
};

hittable_list make_world(const scene& s);

// The built-in scene of that name; throws usage_error naming the choices when there is none.
scene builtin_scene(std::string_view name);
std::vector<std::string> builtin_scene_names();

}  // namespace rtvk
