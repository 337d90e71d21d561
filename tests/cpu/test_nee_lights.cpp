// Next-event estimation with the lights only it can draw, on the CPU: punctual lights give their
// analytic irradiance (inverse square, cosine, a sun's lux), an environment's furnace returns its
// radiance, and an environment-lit scene converges to the plain image.
#include <gtest/gtest.h>

#include <cmath>

#include "environment_scenes.h"
#include "render_cpu.h"
#include "render_helpers.h"
#include "seed_estimates.h"

namespace rtvk {
namespace {

const double pi = 3.14159265358979323846;

// A grey floor (y = 0) seen straight down from height 4 through a narrow pinhole, in the dark,
// one bounce: what each pixel shows is the floor's direct light, albedo / pi times the irradiance.
scene floor_scene(double albedo) {
  scene s;
  s.name = "floor";
  main_camera(s).pose.lookfrom = point3(0, 4, 0);
  main_camera(s).pose.lookat = point3(0, 0, 0);
  main_camera(s).pose.vup = vec3(0, 0, -1);
  main_camera(s).pose.vfov = 60;
  s.render.width = 9;
  s.render.aspect = 1;
  s.render.spp = 1;
  s.render.max_depth = 2;  // the floor's light sample; its BSDF ray meets the black sky
  s.render.sampling = sampling_mode::nee;
  s.sky = {color(0), color(0)};
  s.materials = {{"floor", {material_type::lambertian, color(albedo), 0, 1.5}}};
  s.quads = {{point3(-50, 0, 50), vec3(100, 0, 0), vec3(0, 0, -100), 0}};
  return s;
}

// A point light of 10 cd over a floor of albedo 0.6, placed in turn at heights 1, 2 and 4 over
// the point the image's center sees and beside it: the center pixel is 0.6 / pi * 10 cos(theta)
// / d^2, the inverse square and the cosine (no random number enters a delta light's sample; 1e-4
// for the shadow ray's lift off the floor).
TEST(NeeLights, APointLightsIrradianceFallsAsTheInverseSquareAndTheCosine) {
  for (const point3& at : {point3(0, 1, 0), point3(0, 2, 0), point3(0, 4, 0), point3(1, 1, 0),
                           point3(0, 1, -2), point3(3, 0.5, 1)}) {
    scene s = floor_scene(0.6);
    punctual_light l;
    l.kind = punctual_kind::point;
    l.position = at;
    l.tint = color(1, 0.5, 0.25);
    l.intensity = 10;
    s.punctual_lights.push_back(l);
    const framebuffer fb = render_cpu(test::scene_camera(s), s, s.render);
    const double d2 = glm::dot(at, at), cosine = at.y / std::sqrt(d2);
    const double want = 0.6 / pi * 10 * cosine / d2;
    EXPECT_NEAR(fb.at(4, 4).r, want, 1e-4 * want) << at.x << "," << at.y << "," << at.z;
    EXPECT_NEAR(fb.at(4, 4).b, 0.25 * want, 1e-4 * want) << at.x << "," << at.y << "," << at.z;
  }
}

// A sun of 3 lux, 2 degrees across, 50 degrees above the horizon: the floor's radiance is
// albedo / pi * 3 sin(50 degrees) within the disk's cosine spread (1e-3 of it), everywhere.
TEST(NeeLights, ASunLightsAFloorByItsLuxTimesTheCosine) {
  scene s = floor_scene(0.5);
  s.render.spp = 64;
  punctual_light sun;
  sun.kind = punctual_kind::directional;
  const double elevation = 50 * pi / 180;
  sun.direction = -vec3(std::cos(elevation), std::sin(elevation), 0);
  sun.intensity = 3;
  sun.angular_diameter = 2;
  s.punctual_lights.push_back(sun);
  const framebuffer fb = render_cpu(test::scene_camera(s), s, s.render);
  const double want = 0.5 / pi * 3 * std::sin(elevation);
  for (int y = 0; y < fb.height(); ++y)
    for (int x = 0; x < fb.width(); ++x)
      EXPECT_NEAR(fb.at(x, y).g, want, 1e-3 * want) << x << "," << y;
}

// The white furnace under next-event estimation: a white Lambertian sphere in a uniform map of
// 0.75 is 0.75, the light sample and the escaping BSDF ray weighed by the power heuristic (each
// pixel within 10% (measured: 5% at most), the image's mean within 0.3%, at 64 samples).
TEST(NeeLights, AWhiteSphereInAUniformEnvironmentIsItsRadiance) {
  scene s = test::furnace_scene(0.75f);
  s.render.sampling = sampling_mode::nee;
  s.render.spp = 64;
  const framebuffer fb = render_cpu(test::scene_camera(s), s, s.render);
  double sum = 0;
  for (int y = 0; y < fb.height(); ++y)
    for (int x = 0; x < fb.width(); ++x) {
      EXPECT_NEAR(fb.at(x, y).g, 0.75, 0.1 * 0.75) << x << "," << y;
      sum += fb.at(x, y).g;
    }
  EXPECT_NEAR(sum / (fb.width() * fb.height()), 0.75, 0.003 * 0.75);
}

// Each channel's image mean and its standard error over 24 seeds.
using estimate = test::seed_estimate;
estimate over_seeds(const scene& s) {
  return test::over_seeds(s, 24, 3000);
}

// Three spheres (diffuse, metal, glass) on a floor under a map with one bright texel (50 times
// the rest): next-event estimation's mean equals plain sampling's within 4 standard errors of their
// difference, with less error (the map's sampler finds the bright texel, the BSDF the rest).
TEST(NeeLights, AnEnvironmentLitSceneConvergesToThePlainImage) {
  scene s = test::sunlit_scene();
  s.environment = test::uniform_map(32, 16, 0.4f, 11, 5, 20.0f);
  s.render.width = 16;
  s.render.spp = 16;
  s.render.sampling = sampling_mode::plain;
  const estimate plain = over_seeds(s);
  s.render.sampling = sampling_mode::nee;
  const estimate nee = over_seeds(s);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(nee.mean[c], plain.mean[c], 4 * std::hypot(nee.error[c], plain.error[c]))
        << "channel " << c << ": plain " << plain.mean[c] << " +- " << plain.error[c] << ", nee "
        << nee.mean[c] << " +- " << nee.error[c];
    EXPECT_LT(nee.error[c], plain.error[c]) << "channel " << c;
  }
}

}  // namespace
}  // namespace rtvk
