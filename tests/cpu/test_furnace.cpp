// Statistical checks of the light transport, on the CPU and (where a device exists) the GPU.
#include <gtest/gtest.h>

#include "gpu_fixture.h"
#include "render_helpers.h"

namespace rtvk {
namespace {

// A grey floor (a sphere so large it is a plane here) under the lesson's gradient sky, seen from
// straight above. Lambertian scattering is cosine-weighted, so the mean cosine of a bounce is
// 2/3, the mean sky blend t = (cos + 1) / 2 is 5/6, and the floor's expected color is
// albedo * ((1 - 5/6) * horizon + 5/6 * zenith) = albedo * (7/12, 3/4, 1).
scene grey_floor() {
  scene s;
  s.name = "grey floor";
  main_camera(s).pose.lookfrom = point3(0, 1, 0);
  main_camera(s).pose.lookat = point3(0, 0, 0);
  main_camera(s).pose.vup = vec3(0, 0, -1);
  main_camera(s).pose.vfov = 40;
  s.render.width = 64;
  s.render.aspect = 1;
  s.render.spp = 16;
  s.render.jitter = true;
  s.materials = {{"grey", {material_type::lambertian, color(0.5), 0, 1.5}}};
  s.spheres = {sphere(point3(0, -1e4, 0), 1e4, 0)};
  return s;
}

// The image's mean linear color.
color mean_color(const framebuffer& fb) {
  color sum(0);
  for (int y = 0; y < fb.height(); ++y)
    for (int x = 0; x < fb.width(); ++x) sum += fb.at(x, y);
  return sum / double(fb.width() * fb.height());
}

// 64 * 64 * 16 = 65,536 single-bounce samples; the red channel's sample sd is
// 0.5 * 0.5 * sqrt(1/18) = 0.059, so its standard error is 0.00023. Tolerance: 5 standard errors.
constexpr double tolerance = 0.0012;
const color expected = 0.5 * color(7.0 / 12, 0.75, 1.0);

TEST(Furnace, GreyFloorUnderTheGradientSkyCpu) {
  const scene s = grey_floor();
  const color m = mean_color(render_cpu(test::scene_camera(s), s, s.render));
  EXPECT_NEAR(m.r, expected.r, tolerance);
  EXPECT_NEAR(m.g, expected.g, tolerance);
  EXPECT_NEAR(m.b, expected.b, 1e-9);  // both sky colors have blue 1: no noise at all
}

// White furnace: white lambertian spheres, overlapping into crevices, under a uniform white sky.
// Every path that escapes carries exactly 1, so the whole image must be the sky's white: energy
// is neither lost nor made, however many bounces a path takes.
scene white_furnace() {
  scene s;
  s.name = "white furnace";
  main_camera(s).pose.lookfrom = point3(0, 1, 4);
  main_camera(s).pose.lookat = point3(0, 0, 0);
  s.render.width = 48;
  s.render.spp = 8;
  s.render.jitter = true;
  s.sky = {color(1), color(1)};
  s.materials = {{"white", {material_type::lambertian, color(1), 0, 1.5}}};
  s.spheres = {sphere(point3(0, -100, 0), 99.5, 0), sphere(point3(-0.5, 0, 0), 0.6, 0),
               sphere(point3(0.5, 0, 0), 0.6, 0), sphere(point3(0, 0.6, 0.2), 0.5, 0)};
  return s;
}

TEST(Furnace, WhiteFurnaceIsUniformWhiteCpu) {
  const scene s = white_furnace();
  const framebuffer fb = render_cpu(test::scene_camera(s), s, s.render);
  for (int y = 0; y < fb.height(); ++y)
    for (int x = 0; x < fb.width(); ++x)
      ASSERT_NEAR(fb.at(x, y).r, 1.0, 1e-12) << "pixel " << x << "," << y;
}

class GpuFurnace : public test::GpuTest {};

TEST_F(GpuFurnace, GreyFloorUnderTheGradientSky) {
  const scene s = grey_floor();
  const color m = mean_color(gpu::render_gpu(gpu(), test::scene_camera(s), s, s.render));
  EXPECT_NEAR(m.r, expected.r, tolerance);
  EXPECT_NEAR(m.g, expected.g, tolerance);
  EXPECT_NEAR(m.b, expected.b, 1e-6);
}

TEST_F(GpuFurnace, WhiteFurnaceIsUniformWhite) {
  const scene s = white_furnace();
  const framebuffer fb = gpu::render_gpu(gpu(), test::scene_camera(s), s, s.render);
  for (int y = 0; y < fb.height(); ++y)
    for (int x = 0; x < fb.width(); ++x)
      ASSERT_NEAR(fb.at(x, y).r, 1.0, 1e-5) << "pixel " << x << "," << y;
}

}  // namespace
}  // namespace rtvk
