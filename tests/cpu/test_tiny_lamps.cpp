// Punctual lights against the lamps they idealise (issue 46): a point light of intensity I (W/sr
// in rtvk's units, docs/lighting.md) is the limit of a sphere lamp of radius r at its place whose
// radiance L = I / (pi r^2) emits the same power (4 pi I = 4 pi^2 r^2 L), and a spot whose two
// cones are one angle is the limit of that lamp in an opaque housing with a round hole of that
// angle. Both drawn by next-event estimation on a diffuse floor, direct light only.
#include <gtest/gtest.h>

#include <cmath>

#include "render_cpu.h"
#include "render_helpers.h"

namespace rtvk {
namespace {

const double pi_lamps = 3.14159265358979323846;

// A floor of albedo 0.6 (y = 0) seen from below the lights, straight down from height 0.5 with a
// 120-degree view (the floor within 0.87 of the axis), in the dark: each pixel is the floor's
// direct light (nothing else reflects). The camera stands under the lamp so that no camera ray
// meets it (a sample that saw a lamp of radiance I / (pi r^2) would not vanish as r shrinks).
// Depth 2: the floor's vertex takes its light sample and its BSDF ray is traced (a path's last
// vertex takes none: NeeUnbiased.TheLastVertexCountsAsInTheOtherModesAtEveryDepth).
scene lamp_floor() {
  scene s;
  s.name = "lamp floor";
  main_camera(s).pose.lookfrom = point3(0, 0.5, 0);
  main_camera(s).pose.lookat = point3(0, 0, 0);
  main_camera(s).pose.vup = vec3(0, 0, -1);
  main_camera(s).pose.vfov = 120;
  s.render.width = 16;
  s.render.aspect = 1;
  s.render.spp = 16;
  s.render.max_depth = 2;
  s.render.sampling = sampling_mode::nee;
  s.sky = {color(0), color(0)};
  s.materials = {{"floor", {material_type::lambertian, color(0.6), 0, 1.5}},
                 {"black", {material_type::lambertian, color(0), 0, 1.5}}};
  s.quads = {{point3(-50, 0, 50), vec3(100, 0, 0), vec3(0, 0, -100), 0}};
  return s;
}

// The sphere lamp of radius r at `at` emitting what a point light of intensity `intensity` (tint
// `tint`) does.
void add_sphere_lamp(scene& s, const point3& at, double r, double intensity, const color& tint) {
  material lamp{material_type::diffuse_light, tint * (intensity / (pi_lamps * r * r)), 0, 1.5};
  s.materials.push_back({"lamp", lamp});
  s.spheres.push_back(sphere(at, r, int(s.materials.size()) - 1));
}

// An opaque black plate at height y, from radius `hole` (a 256-sided polygon about the y axis) out
// to radius 2: a lamp above it lights the floor only through the hole.
void add_housing(scene& s, double y, double hole) {
  const int sides = 256;
  for (int k = 0; k < sides; ++k) {
    const double a = 2 * pi_lamps * k / sides, b = 2 * pi_lamps * (k + 1) / sides;
    const point3 ia(hole * std::cos(a), y, hole * std::sin(a));
    const point3 ib(hole * std::cos(b), y, hole * std::sin(b));
    const point3 oa(2 * std::cos(a), y, 2 * std::sin(a)), ob(2 * std::cos(b), y, 2 * std::sin(b));
    s.triangles.push_back({{ia, oa, ob}, 1});
    s.triangles.push_back({{ia, ob, ib}, 1});
  }
}

// The image's mean (green) and its standard error over 24 seeds; one render when `runs` is 1 (a
// delta light's image draws no random number here: no jitter, one bounce).
struct lamp_estimate {
  double mean = 0, error = 0;
  framebuffer first{1, 1};
};
lamp_estimate image_mean(scene s, int runs) {
  const camera cam = test::scene_camera(s);
  std::vector<double> means;
  lamp_estimate out;
  for (int k = 0; k < runs; ++k) {
    s.render.seed = std::uint32_t(5000 + k);
    const framebuffer fb = render_cpu(cam, s, s.render);
    if (k == 0) out.first = fb;
    double m = 0;
    for (int y = 0; y < fb.height(); ++y)
      for (int x = 0; x < fb.width(); ++x) m += fb.at(x, y).g;
    means.push_back(m / (fb.width() * fb.height()));
  }
  for (double m : means) out.mean += m / runs;
  for (double m : means) out.error += (m - out.mean) * (m - out.mean);
  out.error = runs > 1 ? std::sqrt(out.error / (runs - 1) / runs) : 0;
  return out;
}

// A point light of 2 W/sr at (0.3, 1, 0.2) and sphere lamps of radius 0.2, 0.05 and 0.01 there
// with L = 2 / (pi r^2): the image means agree within 4 standard errors of the lamps' estimate,
// and each pixel within 2% at the smallest. (A sphere of uniform radiance wholly above a plane
// gives the plane exactly a point's irradiance, L pi (r/d)^2 cos = I cos / d^2, so the agreement
// holds at every radius here; the small ones are the limit the issue asks for. Measured: 0.202753
// for the point light; 0.202747 +- 7e-6, 0.202752 +- 2e-6 and 0.202753 +- under 1e-6 for the
// lamps.)
TEST(TinyLamps, APointLightIsTheLimitOfASphereLampOfTheSamePower) {
  const point3 at(0.3, 1, 0.2);
  scene point = lamp_floor();
  punctual_light l;
  l.position = at;
  l.intensity = 2;
  point.punctual_lights.push_back(l);
  const lamp_estimate want = image_mean(point, 1);
  ASSERT_GT(want.mean, 0.1);
  for (double r : {0.2, 0.05, 0.01}) {
    scene lamp = lamp_floor();
    add_sphere_lamp(lamp, at, r, 2, color(1));
    const lamp_estimate got = image_mean(lamp, 24);
    EXPECT_NEAR(got.mean, want.mean, 4 * got.error)
        << "r " << r << ": " << got.mean << " +- " << got.error << " against " << want.mean;
    if (r != 0.01) continue;
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 16; ++x)
        EXPECT_NEAR(got.first.at(x, y).g, want.first.at(x, y).g, 0.02 * want.first.at(x, y).g)
            << x << "," << y;
  }
}

// A spot of 2 W/sr at height 1 pointing down, both cones 30 degrees, against the sphere lamp of
// radius 0.01 and the same power in a housing: a black plate 0.2 below it with a round hole whose
// edge is the spot's cone seen from the lamp's center. The floor is lit within tan(30 degrees) =
// 0.58 of the axis, dark beyond. The spot's edge is not quite hard: the extension's falloff with
// equal cones ramps as clamp((cos - cos(outer)) / 0.001)^2 (its max(0.001, ...)), 0.11 degrees
// wide, which lets through what a hard edge 2/3 of the ramp in does; the hole is cut there (cut at
// 30 degrees itself, the lamp's mean was 0.5% above the spot's, 4 standard errors). Jittered
// pixels, so that each mean is the floor's light over the view: the lamp's penumbra (about 2.5
// degrees, 0.05 on the floor) gives outside the edge, to first order, what it takes inside. The
// means agree within 4 standard errors (measured: 0.093828 +- 7e-5 against 0.093682 +- 6e-5, with
// Sobol numbers; 0.093716 +- 1.0e-4 against 0.093649 +- 5e-5 before, and r = 0.003 alike), and
// pixels whose center lies more than 0.15 (a pixel and the penumbra) inside or outside the edge
// within 2%, or both dark.
TEST(TinyLamps, ASpotIsTheLimitOfASphereLampInAHousingWithARoundHole) {
  const double cone = 30 * pi_lamps / 180;
  scene spot = lamp_floor();
  punctual_light l;
  l.kind = punctual_kind::spot;
  l.position = point3(0, 1, 0);
  l.direction = vec3(0, -1, 0);
  l.intensity = 2;
  l.inner_cone = l.outer_cone = 30;
  spot.punctual_lights.push_back(l);
  scene lamp = lamp_floor();
  spot.render.jitter = lamp.render.jitter = true;
  add_sphere_lamp(lamp, point3(0, 1, 0), 0.01, 2, color(1));
  const double edge = std::acos(std::cos(cone) + 0.001 * 2 / 3);
  add_housing(lamp, 0.8, 0.2 * std::tan(edge));
  const lamp_estimate want = image_mean(spot, 24);
  const lamp_estimate got = image_mean(lamp, 24);
  EXPECT_NEAR(got.mean, want.mean, 4 * std::hypot(got.error, want.error))
      << got.mean << " +- " << got.error << " against " << want.mean << " +- " << want.error;
  const camera cam = test::scene_camera(spot);
  int inside = 0, outside = 0;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const ray r = cam.get_ray((x + 0.5) / 15, (15 - y + 0.5) / 15);
      const point3 g = r.origin - r.origin.y / r.direction.y * r.direction;
      const double off = std::hypot(g.x, g.z) - std::tan(cone);
      if (std::abs(off) < 0.15) continue;
      off < 0 ? ++inside : ++outside;
      EXPECT_NEAR(got.first.at(x, y).g, want.first.at(x, y).g, 0.02 * want.first.at(x, y).g)
          << x << "," << y << (off < 0 ? " inside" : " outside");
    }
  EXPECT_GE(inside, 40);
  EXPECT_GE(outside, 40);
}

}  // namespace
}  // namespace rtvk
