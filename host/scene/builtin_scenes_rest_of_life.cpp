// "Ray Tracing: The Rest of Your Life": its final Cornell box.
#include <algorithm>
#include <cmath>
#include <memory>

#include "builtin_scene_parts.h"
#include "random.h"

namespace rtvk::builtin {

// "The Rest of Your Life", its final scene (main.cc of the book's source): the Cornell box with
// its tall box and a glass sphere, the lamp lit from its front only (the third book's
// diffuse_light), and the glass sphere aimed at by lights sampling beside the lamp (the book's
// `lights` list). 100 samples, as the book's main.
scene rest_of_life_final_scene() {
  scene s;
  s.name = "rest-of-life-final";
  const auto [red, white, green] = cornell_setup(s, 100);
  material front_lamp = lamp(color(15, 15, 15));
  front_lamp.one_sided = true;
  const int light = add_material(s, "light", front_lamp);
  const int glass = add_material(s, "glass", dielectric(1.5));
  s.quads.push_back({point3(555, 0, 0), vec3(0, 0, 555), vec3(0, 555, 0), green});
  s.quads.push_back({point3(0, 0, 555), vec3(0, 0, -555), vec3(0, 555, 0), red});
  s.quads.push_back({point3(0, 555, 0), vec3(555, 0, 0), vec3(0, 0, 555), white});
  s.quads.push_back({point3(0, 0, 555), vec3(555, 0, 0), vec3(0, 0, -555), white});
  s.quads.push_back({point3(555, 0, 555), vec3(-555, 0, 0), vec3(0, 555, 0), white});
  s.quads.push_back({point3(213, 554, 227), vec3(130, 0, 0), vec3(0, 0, 105), light});
  add_box(s, point3(0, 0, 0), point3(165, 330, 165), white,
          turned_and_moved(15, vec3(265, 0, 295)));
  sphere ball(point3(190, 90, 190), 90, glass);
  ball.sampled = true;
  s.spheres.push_back(ball);
  return s;
}

}  // namespace rtvk::builtin
