// The built-in scenes by name (each book's are in its own file: builtin_scene_parts.h).
#include <charconv>

#include "builtin_scene_parts.h"
#include "errors.h"
#include "scene.h"

namespace rtvk {
namespace {

// Each built-in scene's name and maker, in the order `rtvk scene list` prints them.
struct builtin_entry {
  const char* name;
  scene (*make)();
};
constexpr builtin_entry builtins[] = {
    {"seed", builtin::seed_scene},
    {"materials", builtin::materials_scene},
    {"book-final", builtin::book_final_scene},
    {"bouncing-spheres", builtin::bouncing_spheres_scene},
    {"quads", builtin::quads_scene},
    {"checkered-spheres", builtin::checkered_spheres_scene},
    {"perlin-spheres", builtin::perlin_spheres_scene},
    {"simple-light", builtin::simple_light_scene},
    {"cornell-box", builtin::cornell_box_scene},
    {"cornell-smoke", builtin::cornell_smoke_scene},
    {"next-week-final", builtin::next_week_final_scene},
    {"rest-of-life-final", builtin::rest_of_life_final_scene},
};

}  // namespace

std::vector<std::string> builtin_scene_names() {
  std::vector<std::string> names;
  for (const builtin_entry& b : builtins) names.push_back(b.name);
  return names;
}

scene builtin_scene(std::string_view name) {
  for (const builtin_entry& b : builtins)
    if (name == b.name) return b.make();
  if (name.rfind("spheres:", 0) == 0) {
    const std::string_view count = name.substr(8);
    std::uint32_t n = 0;
    const auto [end, ec] = std::from_chars(count.data(), count.data() + count.size(), n);
    if (ec != std::errc() || end != count.data() + count.size() || n < 1 || n > max_scene_spheres)
      throw usage_error("--scene: '" + std::string(name) +
                        "': expected spheres:N with N from 1 to " +
                        std::to_string(max_scene_spheres));
    return builtin::spheres_scene(n);
  }
  std::string choices;
  for (const auto& n : builtin_scene_names()) choices += (choices.empty() ? "" : ", ") + n;
  throw usage_error(
      "--scene: unknown scene '" + std::string(name) + "' (built-in: " + choices +
      ", spheres:N, showcase; or a .json scene file, or an .obj, .gltf or .glb mesh)");
}

}  // namespace rtvk
