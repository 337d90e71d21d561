// Next-event estimation (--sampling nee) on the GPU: the same steps as the CPU's
// (tests/cpu/test_nee.cpp), the shadow ray traced in a trip of its own through the one world
// search; the images match the CPU's by the rule GpuBook's scenes follow, and the hardware paths
// give the compute BVH's exact sums.
#include <gtest/gtest.h>

#include "environment_scenes.h"
#include "gpu_engine.h"
#include "gpu_fixture.h"
#include "hardware_sums.h"
#include "image_compare.h"
#include "pbr_scenes.h"
#include "render_gpu.h"
#include "render_helpers.h"

namespace rtvk {
namespace {

class GpuNee : public test::GpuTest {
 protected:
  GpuNee() { ray_tracing_ = true; }
};

scene nee_scene(scene s) {
  s.render.sampling = sampling_mode::nee;
  return s;
}

// The Cornell box (a one-sided quad lamp, Lambertian walls, two boxes) and the PBR gallery (its
// lobes, a lamp quad and the sky) against the CPU, by the rule GpuBook's scenes follow. Measured on
// lavapipe 22.3 (2026-11-28, Sobol numbers in every dimension): the smoky box's bytes equal the
// CPU's (PSNR infinite); the gallery's PSNR is 63.3 dB, no pixel over 2 levels (a path or two
// that float and double round apart at its glossy lobes). Two tests: the gallery's PBR variant
// compiles for minutes on Mesa 25's lavapipe, whose pass leaves it out (scripts/test.sh).
void expect_cpus_image(gpu::gpu_context& ctx, const scene& s, double measured_psnr_db = 73) {
  const image_rgb8 cpu = test::cpu_image(s);
  const image_difference d =
      compare_images(test::gpu_image(ctx, s), cpu, monte_carlo_agreement.tolerance);
  const agreement rule = test::measured_agreement(measured_psnr_db, 0, cpu.width * cpu.height);
  EXPECT_GE(d.psnr_db, rule.min_psnr_db);
  EXPECT_LE(d.share_over, rule.max_share) << d.pixels_over << " pixels over 2 levels";
}

// The smoke-filled box (cornell-smoke): its media scatter both the paths and the shadow rays, each
// by its own numbers; the plain box's variant is the gallery's without PBR.
TEST_F(GpuNee, TheSmokyCornellBoxMatchesTheCpu) {
  expect_cpus_image(gpu(), nee_scene(test::small_scene("cornell-smoke", 40, 16)));
}

TEST_F(GpuNee, ThePbrGalleryMatchesTheCpu) {
  expect_cpus_image(gpu(), nee_scene(test::pbr_gallery()), 63);
}

// The lights only next-event estimation draws, all at once: three spheres on a floor under a map
// with a bright texel, a point light, a spot and a sun (each kind drawn a third of the time, the
// map's and the sun's samples weighed against the escaping rays): the GPU draws the CPU's image.
scene lit_by_everything() {
  scene s = test::sunlit_scene();
  s.environment = test::uniform_map(32, 16, 0.4f, 11, 5, 20.0f);
  s.render.width = 32;
  s.render.spp = 8;
  s.render.sampling = sampling_mode::nee;
  punctual_light point, spot, sun;
  point.position = point3(-1, 2, 1);
  point.intensity = 4;
  spot.kind = punctual_kind::spot;
  spot.position = point3(1.5, 3, 1);
  spot.direction = vec3(-0.4, -1, -0.3);
  spot.inner_cone = 10;
  spot.outer_cone = 25;
  spot.intensity = 30;
  sun.kind = punctual_kind::directional;
  sun.direction = vec3(-0.5, -0.8, -0.3);
  sun.intensity = 2;
  sun.angular_diameter = 3;
  s.punctual_lights = {point, spot, sun};
  return s;
}

TEST_F(GpuNee, TheEnvironmentAndPunctualLightsMatchTheCpu) {
  expect_cpus_image(gpu(), lit_by_everything());
}

// The hardware paths trace the shadow rays as the compute BVH does: the same sums exactly.
TEST_F(GpuNee, TheHardwarePathsGiveTheComputeBvhsExactSums) {
  for (const scene& s : {nee_scene(test::small_scene("cornell-box", 24, 4)), lit_by_everything()})
    test::expect_hardware_paths_match(gpu(), s);
}

}  // namespace
}  // namespace rtvk
