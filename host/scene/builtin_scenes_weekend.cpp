// "Ray Tracing in One Weekend": the lesson's seed, the materials chapter and the cover (and the
// second book's first scene, the cover bouncing), and spheres:N over the cover's ground.
#include <algorithm>
#include <cmath>
#include <memory>

#include "builtin_scene_parts.h"
#include "random.h"

namespace rtvk::builtin {

// The lesson's world: one sphere in front of the camera resting on a huge "ground" sphere,
// colored by normals at one sample per pixel, as the lesson draws it.
scene seed_scene() {
  scene s;
  s.name = "seed";
  s.materials = {{"normal", material{}}};
  s.spheres = {sphere(point3(0, 0, -1), 0.5, 0), sphere(point3(0, -100.5, -1), 100, 0)};
  return s;
}

// The book's materials chapter: ground, a diffuse center, hollow glass on the left (an inner
// sphere of index 1/1.5 makes the bubble, rather than the first edition's negative radius), and
// polished metal on the right, seen through the defocus-blur chapter's camera.
scene materials_scene() {
  scene s;
  s.name = "materials";
  camera_pose& c = main_camera(s).pose;
  c.lookfrom = point3(3, 3, 2);
  c.lookat = point3(0, 0, -1);
  c.vfov = 20;
  c.aperture = 2.0;
  c.focus_dist = glm::length(c.lookfrom - c.lookat);
  s.render = book_render(400, 16.0 / 9.0, 100);
  s.materials = {{"ground", lambertian(color(0.8, 0.8, 0.0))},
                 {"center", lambertian(color(0.1, 0.2, 0.5))},
                 {"glass", dielectric(1.5)},
                 {"bubble", dielectric(1.0 / 1.5)},
                 {"gold", metal(color(0.8, 0.6, 0.2), 0.0)}};
  s.spheres = {sphere(point3(0, -100.5, -1), 100, 0), sphere(point3(0, 0, -1), 0.5, 1),
               sphere(point3(-1, 0, -1), 0.5, 2), sphere(point3(-1, 0, -1), 0.4, 3),
               sphere(point3(1, 0, -1), 0.5, 4)};
  return s;
}

// The book's cover: a grid of small random spheres around three large ones. The random numbers
// come from the counter-based generator with a fixed seed, so the scene is the same every run
// and on every machine. `bouncing`: the second book's first scene, where each small diffuse
// sphere rises by up to half a unit between times 0 and 1 (its rise drawn after its color).
void add_book_cover(scene& s, bool bouncing) {
  std::uint32_t counter = 0;
  auto rnd = [&counter] { return double(random_float(0x5eed, counter++, 0, 0, 0)); };
  auto add = [&s](const std::string& name, material m) {
    s.materials.push_back({name, m});
    return int(s.materials.size() - 1);
  };

  s.spheres.push_back(sphere(point3(0, -1000, 0), 1000, add("ground", lambertian(color(0.5)))));
  for (int a = -11; a < 11; ++a) {
    for (int b = -11; b < 11; ++b) {
      const double choose_mat = rnd();
      const double cx = a + 0.9 * rnd();
      const point3 center(cx, 0.2, b + 0.9 * rnd());
      if (glm::length(center - point3(4, 0.2, 0)) <= 0.9) continue;
      const std::string name = "small_" + std::to_string(a + 11) + "_" + std::to_string(b + 11);
      material m;
      std::optional<point3> center1;
      if (choose_mat < 0.8) {
        const color c1(rnd(), rnd(), rnd());
        const color c2(rnd(), rnd(), rnd());
        m = lambertian(c1 * c2);
        if (bouncing) center1 = center + vec3(0, 0.5 * rnd(), 0);
      } else if (choose_mat < 0.95) {
        const color albedo(0.5 + 0.5 * rnd(), 0.5 + 0.5 * rnd(), 0.5 + 0.5 * rnd());
        m = metal(albedo, 0.5 * rnd());
      } else {
        m = dielectric(1.5);
      }
      s.spheres.push_back(sphere(center, 0.2, add(name, m), center1));
    }
  }
  s.spheres.push_back(sphere(point3(0, 1, 0), 1.0, add("big_glass", dielectric(1.5))));
  s.spheres.push_back(
      sphere(point3(-4, 1, 0), 1.0, add("big_diffuse", lambertian(color(0.4, 0.2, 0.1)))));
  s.spheres.push_back(
      sphere(point3(4, 1, 0), 1.0, add("big_metal", metal(color(0.7, 0.6, 0.5), 0.0))));
}

// The first book's camera on its cover.
camera_pose& book_cover_camera(scene& s) {
  camera_pose& c = main_camera(s).pose;
  c.lookfrom = point3(13, 2, 3);
  c.lookat = point3(0, 0, 0);
  c.vfov = 20;
  c.aperture = 0.1;
  c.focus_dist = 10;
  return c;
}

scene book_final_scene() {
  scene s;
  s.name = "book-final";
  book_cover_camera(s);
  s.render = book_render(1200, 3.0 / 2.0, 500);
  add_book_cover(s, false);
  return s;
}

// "Ray Tracing: The Next Week", chapter 2: the cover with its diffuse spheres bouncing, seen
// by the same camera with the shutter open from time 0 to 1, 400 pixels wide at 16:9, 100 spp.
scene bouncing_spheres_scene() {
  scene s;
  s.name = "bouncing-spheres";
  camera_pose& c = book_cover_camera(s);
  c.shutter_open = 0;
  c.shutter_close = 1;
  s.render = book_render(400, 16.0 / 9.0, 100);
  add_book_cover(s, true);
  return s;
}

// N small spheres scattered over the book-final ground, for scaling runs. The area grows with N
// (about one sphere per square unit, as in the book's grid), so what a ray sees stays alike and
// only the BVH's depth grows. Materials come from a palette of 64 in the book's mix.
scene spheres_scene(std::uint32_t n) {
  scene s = book_final_scene();
  s.name = "spheres:" + std::to_string(n);
  s.render.spp = 10;
  s.materials.resize(1);  // keep the ground
  s.spheres.resize(1);
  std::uint32_t counter = 0;
  auto rnd = [&counter] { return double(random_float(0xba11, counter++, 0, 0, 0)); };
  for (int k = 0; k < 64; ++k) {
    const double choose = rnd();
    material m;
    if (choose < 0.8) {
      const color c1(rnd(), rnd(), rnd()), c2(rnd(), rnd(), rnd());
      m = lambertian(c1 * c2);
    } else if (choose < 0.95) {
      m = metal(color(0.5 + 0.5 * rnd(), 0.5 + 0.5 * rnd(), 0.5 + 0.5 * rnd()), 0.5 * rnd());
    } else {
      m = dielectric(1.5);
    }
    s.materials.push_back({"palette_" + std::to_string(k), m});
  }
  const double side = std::max(22.0, std::sqrt(double(n)));
  const double ground = 1000;  // radius of the book's ground sphere, centered at (0, -1000, 0)
  s.spheres.reserve(n + 1);
  const double rest = ground + 0.2;  // a center's distance from the ground's center
  for (std::uint32_t i = 0; i < n; ++i) {
    // Above 2,000,000 spheres the square is wider than the ground: points beyond its edge are
    // drawn again. Up to 2,000,000 every point of the square (x^2 + z^2 <= side^2 / 2 <= 10^6)
    // is inside it, so those scenes are as they always were.
    double x, z;
    do {
      x = side * (rnd() - 0.5);
      z = side * (rnd() - 0.5);
    } while (x * x + z * z >= rest * rest);
    // Resting on the ground: the center is radius + 0.2 from the ground's center.
    const double y = std::sqrt(rest * rest - x * x - z * z) - ground;
    s.spheres.push_back(sphere(point3(x, y, z), 0.2, 1 + int(hash32(i) % 64)));
  }
  return s;
}

}  // namespace rtvk::builtin
