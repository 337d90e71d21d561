// "Ray Tracing: The Next Week": quads, textures, lamps, the Cornell box and its smoke, and the
// book's final scene.
#include <algorithm>
#include <cmath>
#include <memory>

#include "builtin_scene_parts.h"
#include "random.h"

namespace rtvk::builtin {

// "Ray Tracing: The Next Week", chapter 6: five quads, one per side of a box open at the front,
// lit by a constant light-blue background, as the book defines them.
scene quads_scene() {
  scene s;
  s.name = "quads";
  camera_pose& c = main_camera(s).pose;
  c.lookfrom = point3(0, 0, 9);
  c.lookat = point3(0, 0, 0);
  c.vup = vec3(0, 1, 0);
  c.vfov = 80;
  c.aperture = 0;
  s.render = book_render(400, 1.0, 100);
  s.sky.horizon = s.sky.zenith = color(0.70, 0.80, 1.00);
  s.materials = {{"left_red", lambertian(color(1.0, 0.2, 0.2))},
                 {"back_green", lambertian(color(0.2, 1.0, 0.2))},
                 {"right_blue", lambertian(color(0.2, 0.2, 1.0))},
                 {"upper_orange", lambertian(color(1.0, 0.5, 0.0))},
                 {"lower_teal", lambertian(color(0.2, 0.8, 0.8))}};
  s.quads = {{point3(-3, -2, 5), vec3(0, 0, -4), vec3(0, 4, 0), 0},
             {point3(-2, -2, 0), vec3(4, 0, 0), vec3(0, 4, 0), 1},
             {point3(3, -2, 1), vec3(0, 0, 4), vec3(0, 4, 0), 2},
             {point3(-2, 3, 1), vec3(4, 0, 0), vec3(0, 0, 4), 3},
             {point3(-2, -3, 5), vec3(4, 0, 0), vec3(0, 0, -4), 4}};
  return s;
}

// "The Next Week", chapter 4: two large spheres in the spatial checker (cells of 0.32 units).
scene checkered_spheres_scene() {
  scene s = next_week_scene("checkered-spheres", point3(13, 2, 3), point3(0, 0, 0),
                            color(0.70, 0.80, 1.00));
  texture checker;
  checker.type = texture_type::checker;
  checker.scale = 0.32;
  checker.even = color(0.2, 0.3, 0.1);
  checker.odd = color(0.9, 0.9, 0.9);
  const int m = add_material(s, "checker", textured(s, checker));
  s.spheres = {sphere(point3(0, -10, 0), 10, m), sphere(point3(0, 10, 0), 10, m)};
  return s;
}

// Chapter 5's marble: the ground and a sphere in the book's noise texture (scale 4).
void add_perlin_spheres(scene& s) {
  const int m = add_material(s, "marble", textured(s, noise_texture(4)));
  s.spheres.push_back(sphere(point3(0, -1000, 0), 1000, m));
  s.spheres.push_back(sphere(point3(0, 2, 0), 2, m));
}

scene perlin_spheres_scene() {
  scene s =
      next_week_scene("perlin-spheres", point3(13, 2, 3), point3(0, 0, 0), color(0.70, 0.80, 1.00));
  add_perlin_spheres(s);
  return s;
}

// Chapter 7: the marble spheres lit by a lamp sphere and a lamp quad, in the dark.
scene simple_light_scene() {
  scene s = next_week_scene("simple-light", point3(26, 3, 6), point3(0, 2, 0), color(0, 0, 0));
  add_perlin_spheres(s);
  const int light = add_material(s, "light", lamp(color(4, 4, 4)));
  s.spheres.push_back(sphere(point3(0, 7, 0), 2, light));
  s.quads.push_back({point3(3, 1, -2), vec3(2, 0, 0), vec3(0, 2, 0), light});
  return s;
}

// Chapter 8: the Cornell box with its two boxes, turned and moved as the book turns them.
scene cornell_box_scene() {
  scene s;
  s.name = "cornell-box";
  const int white = add_cornell_walls(s, color(15, 15, 15), point3(343, 554, 332), vec3(-130, 0, 0),
                                      vec3(0, 0, -105), false);
  add_box(s, point3(0, 0, 0), point3(165, 330, 165), white,
          turned_and_moved(15, vec3(265, 0, 295)));
  add_box(s, point3(0, 0, 0), point3(165, 165, 165), white,
          turned_and_moved(-18, vec3(130, 0, 65)));
  return s;
}

// Chapter 9: the boxes as smoke (black and white fog of density 0.01) under a larger lamp.
scene cornell_smoke_scene() {
  scene s;
  s.name = "cornell-smoke";
  add_cornell_walls(s, color(7, 7, 7), point3(113, 554, 127), vec3(330, 0, 0), vec3(0, 0, 305),
                    true);
  const int black_smoke = add_material(s, "black_smoke", isotropic(color(0, 0, 0)));
  const int white_smoke = add_material(s, "white_smoke", isotropic(color(1, 1, 1)));
  medium tall;
  tall.shape = boundary_shape::box;
  tall.hi = point3(165, 330, 165);
  tall.placement = turned_and_moved(15, vec3(265, 0, 295));
  tall.density = 0.01;
  tall.material = black_smoke;
  medium short_box = tall;
  short_box.hi = point3(165, 165, 165);
  short_box.placement = turned_and_moved(-18, vec3(130, 0, 65));
  short_box.material = white_smoke;
  s.media = {tall, short_box};
  return s;
}

// Chapter 10, the book's final scene: a floor of random boxes, a lamp, a moving sphere, glass,
// brushed metal, a glass sphere full of blue fog, a thin mist over everything, a textured planet
// (rtvk's own image: builtin:planet), a marble sphere, and a turned cluster of 1000 small white
// spheres (one group, placed once). Random numbers are rtvk's own, from a fixed seed.
scene next_week_final_scene() {
  scene s;
  s.name = "next-week-final";
  next_week_camera(s, point3(478, 278, -600), point3(278, 278, 0), 40);
  main_camera(s).pose.shutter_open = 0;
  main_camera(s).pose.shutter_close = 1;
  s.render = book_render(800, 1.0, 10000);
  s.render.max_depth = 40;
  s.sky.horizon = s.sky.zenith = color(0, 0, 0);
  std::uint32_t counter = 0;
  auto rnd = [&counter] { return double(random_float(0xf1a1, counter++, 0, 0, 0)); };
  const int ground = add_material(s, "ground", lambertian(color(0.48, 0.83, 0.53)));
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j) {
      const double w = 100, x0 = -1000 + i * w, z0 = -1000 + j * w;
      add_box(s, point3(x0, 0, z0), point3(x0 + w, 1 + 100 * rnd(), z0 + w), ground);
    }
  s.quads.push_back({point3(123, 554, 147), vec3(300, 0, 0), vec3(0, 0, 265),
                     add_material(s, "light", lamp(color(7, 7, 7)))});
  s.spheres.push_back(sphere(point3(400, 400, 200), 50,
                             add_material(s, "orange", lambertian(color(0.7, 0.3, 0.1))),
                             point3(430, 400, 200)));
  const int glass = add_material(s, "glass", dielectric(1.5));
  s.spheres.push_back(sphere(point3(260, 150, 45), 50, glass));
  s.spheres.push_back(sphere(point3(0, 150, 145), 50,
                             add_material(s, "brushed", metal(color(0.8, 0.8, 0.9), 1.0))));
  s.spheres.push_back(sphere(point3(360, 150, 145), 70, glass));
  medium blue;
  blue.center = point3(360, 150, 145);
  blue.radius = 70;
  blue.density = 0.2;
  blue.material = add_material(s, "blue_fog", isotropic(color(0.2, 0.4, 0.9)));
  medium mist;
  mist.radius = 5000;
  mist.density = 0.0001;
  mist.material = add_material(s, "mist", isotropic(color(1, 1, 1)));
  s.media = {blue, mist};
  texture planet;
  planet.type = texture_type::image;
  planet.file = builtin_planet;
  planet.image = planet_image(1024, 512, 0);
  s.spheres.push_back(
      sphere(point3(400, 200, 400), 100, add_material(s, "planet", textured(s, planet))));
  s.spheres.push_back(sphere(point3(220, 280, 300), 80,
                             add_material(s, "marble", textured(s, noise_texture(0.2)))));
  object_group cluster;
  cluster.name = "cluster";
  const int white = add_material(s, "white", lambertian(color(.73, .73, .73)));
  for (int j = 0; j < 1000; ++j) {
    const point3 c(165 * rnd(), 165 * rnd(), 165 * rnd());
    cluster.spheres.push_back(sphere(c, 10, white));
  }
  s.groups.push_back(std::move(cluster));
  s.instances.push_back({0, turned_and_moved(15, vec3(-100, 270, 395))});
  return s;
}

}  // namespace rtvk::builtin
