#include "scene.h"

#include <memory>

#include "errors.h"

namespace rtvk {
namespace {

// The lesson's world: one sphere in front of the camera resting on a huge "ground" sphere.
scene seed_scene() {
  return scene{"seed", {sphere(point3(0, 0, -1), 0.5), sphere(point3(0, -100.5, -1), 100)}};
}

}  // namespace

hittable_list make_world(const scene& s) {
  hittable_list world;
  for (const sphere& sp : s.spheres) world.add(std::make_shared<sphere>(sp));
  return world;
}

std::vector<std::string> builtin_scene_names() {
  return {"seed"};
}

scene builtin_scene(std::string_view name) {
  if (name == "seed") return seed_scene();
  std::string choices;
  for (const auto& n : builtin_scene_names()) choices += (choices.empty() ? "" : ", ") + n;
  throw usage_error("--scene: unknown scene '" + std::string(name) + "' (built-in: " + choices +
                    ")");
}

}  // namespace rtvk
