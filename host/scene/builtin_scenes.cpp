#include "scene.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <memory>

#include "errors.h"
#include "format.h"
#include "random.h"

namespace rtvk {
namespace {

// The lesson's world: one sphere in front of the camera resting on a huge "ground" sphere,
// colored by normals at one sample per pixel, as the lesson draws it.
scene seed_scene() {
  scene s;
  s.name = "seed";
  s.materials = {{"normal", material{}}};
  s.spheres = {sphere(point3(0, 0, -1), 0.5, 0), sphere(point3(0, -100.5, -1), 100, 0)};
  return s;
}

material lambertian(color albedo) {
  return {material_type::lambertian, albedo, 0, 1.5};
}
material metal(color albedo, double fuzz) {
  return {material_type::metal, albedo, fuzz, 1.5};
}
material dielectric(double ir) {
  return {material_type::dielectric, color(1), 0, ir};
}

render_settings book_render(int width, double aspect, int spp) {
  render_settings r;
  r.width = width;
  r.aspect = aspect;
  r.spp = spp;
  r.max_depth = 50;
  r.gamma = 2;
  r.jitter = true;
  return r;
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

material lamp(color emit) {
  return {material_type::diffuse_light, emit, 0, 1.5};
}
material isotropic(color albedo) {
  return {material_type::isotropic, albedo, 0, 1.5};
}
// A lambertian colored by texture t, which is appended to the scene.
material textured(scene& s, texture t) {
  material m = lambertian(color(1));
  m.texture = int(s.textures.size());
  s.textures.push_back(std::move(t));
  return m;
}
texture noise_texture(double scale) {
  texture t;
  t.type = texture_type::noise;
  t.scale = scale;
  return t;
}
int add_material(scene& s, const std::string& name, material m) {
  s.materials.push_back({name, m});
  return int(s.materials.size() - 1);
}
// The book's rotate_y by `degrees`, then translate by `offset`.
transform turned_and_moved(double degrees, const vec3& offset) {
  return make_transform(vec3(1), vec3(0, 1, 0), degrees, offset);
}
// The second book's cameras: the lookfrom, lookat and field of view given, no lens.
void next_week_camera(scene& s, const point3& from, const point3& at, double vfov) {
  camera_pose& c = main_camera(s).pose;
  c.lookfrom = from;
  c.lookat = at;
  c.vup = vec3(0, 1, 0);
  c.vfov = vfov;
  c.aperture = 0;
}

// The second book's early scenes' set-up: 400 pixels wide at 16:9, 100 samples, the camera at
// `from` looking at `at` (vfov 20), a constant background.
scene next_week_scene(const std::string& name, const point3& from, const point3& at,
                      const color& background) {
  scene s;
  s.name = name;
  next_week_camera(s, from, at, 20);
  s.render = book_render(400, 16.0 / 9.0, 100);
  s.sky.horizon = s.sky.zenith = background;
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

// The Cornell box's camera, its dark background and its walls' three materials, as both books
// set them up.
struct cornell_colors {
  int red, white, green;  // material indices
};
cornell_colors cornell_setup(scene& s, int spp) {
  next_week_camera(s, point3(278, 278, -800), point3(278, 278, 0), 40);
  s.render = book_render(600, 1.0, spp);
  s.sky.horizon = s.sky.zenith = color(0, 0, 0);
  return {add_material(s, "red", lambertian(color(.65, .05, .05))),
          add_material(s, "white", lambertian(color(.73, .73, .73))),
          add_material(s, "green", lambertian(color(.12, .45, .15)))};
}

// The Cornell box's walls (green right, red left, white floor, ceiling and back), its lamp of
// `light` at (Q, u, v), and the book's camera. Returns the white material.
int add_cornell_walls(scene& s, color light, const point3& Q, const vec3& u, const vec3& v,
                      bool smoke) {
  const auto [red, white, green] = cornell_setup(s, 200);
  const int lit = add_material(s, "light", lamp(light));
  s.quads.push_back({point3(555, 0, 0), vec3(0, 555, 0), vec3(0, 0, 555), green});
  s.quads.push_back({point3(0, 0, 0), vec3(0, 555, 0), vec3(0, 0, 555), red});
  if (smoke) {  // cornell_smoke lists the lamp and the walls in this order, with these corners
    s.quads.push_back({Q, u, v, lit});
    s.quads.push_back({point3(0, 555, 0), vec3(555, 0, 0), vec3(0, 0, 555), white});
    s.quads.push_back({point3(0, 0, 0), vec3(555, 0, 0), vec3(0, 0, 555), white});
  } else {
    s.quads.push_back({Q, u, v, lit});
    s.quads.push_back({point3(0, 0, 0), vec3(555, 0, 0), vec3(0, 0, 555), white});
    s.quads.push_back({point3(555, 555, 555), vec3(-555, 0, 0), vec3(0, 0, -555), white});
  }
  s.quads.push_back({point3(0, 0, 555), vec3(555, 0, 0), vec3(0, 555, 0), white});
  return white;
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

}  // namespace

std::vector<std::string> builtin_scene_names() {
  return {"seed",        "materials",         "book-final",      "bouncing-spheres",
          "quads",       "checkered-spheres", "perlin-spheres",  "simple-light",
          "cornell-box", "cornell-smoke",     "next-week-final", "rest-of-life-final"};
}

scene builtin_scene(std::string_view name) {
  if (name == "seed") return seed_scene();
  if (name == "materials") return materials_scene();
  if (name == "book-final") return book_final_scene();
  if (name == "bouncing-spheres") return bouncing_spheres_scene();
  if (name == "quads") return quads_scene();
  if (name == "checkered-spheres") return checkered_spheres_scene();
  if (name == "perlin-spheres") return perlin_spheres_scene();
  if (name == "simple-light") return simple_light_scene();
  if (name == "cornell-box") return cornell_box_scene();
  if (name == "cornell-smoke") return cornell_smoke_scene();
  if (name == "next-week-final") return next_week_final_scene();
  if (name == "rest-of-life-final") return rest_of_life_final_scene();
  if (name.rfind("spheres:", 0) == 0) {
    const std::string_view count = name.substr(8);
    std::uint32_t n = 0;
    const auto [end, ec] = std::from_chars(count.data(), count.data() + count.size(), n);
    if (ec != std::errc() || end != count.data() + count.size() || n < 1 || n > max_scene_spheres)
      throw usage_error("--scene: '" + std::string(name) +
                        "': expected spheres:N with N from 1 to " +
                        std::to_string(max_scene_spheres));
    return spheres_scene(n);
  }
  std::string choices;
  for (const auto& n : builtin_scene_names()) choices += (choices.empty() ? "" : ", ") + n;
  throw usage_error("--scene: unknown scene '" + std::string(name) + "' (built-in: " + choices +
                    ", spheres:N; or a .json scene file, or an .obj, .gltf or .glb mesh)");
}

}  // namespace rtvk
