// HDR environment maps on the device (issue 46): what escaping rays see agrees with the CPU.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

#include <glm/geometric.hpp>

#include "environment_scenes.h"
#include "gpu/kernels_f32.h"
#include "gpu_engine.h"
#include "gpu_fixture.h"
#include "hardware_sums.h"
#include "image_compare.h"
#include "probe.h"
#include "render_helpers.h"

namespace rtvk {
namespace {

class GpuEnvironment : public test::GpuTest {
 protected:
  // The sums of a render of `s` on traversal `t` (as GpuPbr's).
};

// The white furnace of tests/scene/test_environment.cpp on the device: L everywhere.
TEST_F(GpuEnvironment, AWhiteSphereInAUniformEnvironmentIsItsRadiance) {
  const scene s = test::furnace_scene(0.75f);
  const framebuffer fb = gpu::render_gpu(gpu(), test::scene_camera(s), s, s.render);
  for (int y = 0; y < fb.height(); ++y)
    for (int x = 0; x < fb.width(); ++x)
      ASSERT_NEAR(fb.at(x, y).g, 0.75, 1e-5) << "pixel " << x << "," << y;
}

// Camera rays that escape see the sky where the map is not visible; the sphere sees the map.
TEST_F(GpuEnvironment, AnInvisibleMapShowsTheSkyToCameraRaysOnly) {
  scene s = test::furnace_scene(0.75f);
  s.environment->visible = false;
  s.sky = {color(0.1), color(0.1)};
  const framebuffer fb = gpu::render_gpu(gpu(), test::scene_camera(s), s, s.render);
  EXPECT_NEAR(fb.at(0, 0).g, 0.1, 1e-6);
  EXPECT_NEAR(fb.at(12, 12).g, 0.75, 1e-5);
}

// The test map's sun over diffuse, metal and glass spheres: the device's image is the CPU's.
// Measured on lavapipe (Mesa 22.3.6): 72.2 dB, no pixel over 2 levels (measured_agreement's
// margin below that).
TEST_F(GpuEnvironment, ASunlitSceneMatchesTheCpu) {
  const scene s = test::sunlit_scene();
  const image_rgb8 cpu = test::cpu_image(s);
  const image_difference d =
      compare_images(test::gpu_image(gpu(), s), cpu, monte_carlo_agreement.tolerance);
  const agreement rule = test::measured_agreement(72, 0, cpu.width * cpu.height);
  EXPECT_GE(d.psnr_db, rule.min_psnr_db);
  EXPECT_LE(d.share_over, rule.max_share) << d.pixels_over << " pixels over 2 levels";
}

// The hardware paths see the map as the compute BVH does: the same sums exactly (Mesa 25's
// lavapipe: the sunlit scene's 48x32 pixels; skipped where the device has no ray tracing).
TEST_F(GpuEnvironment, TheHardwarePathsGiveTheComputeBvhsExactSums) {
  scene s = test::sunlit_scene();
  s.render.spp = 4;
  test::expect_hardware_paths_match(gpu(), s);
}

class GpuEnvironmentKernels : public test::GpuTest {};

// environment.h on the device against its float compilation, on the test map turned 30 degrees:
// a sample's binary searches compare the same floats, so it falls in the same texel and its
// radiance is the same bits; its direction and density within 2e-3 (Vulkan's sin, cos, atan and
// acos may be 2^-11 off). A query direction on a texel's edge may round into its neighbor on one
// side: at most 1% of them differ.
TEST_F(GpuEnvironmentKernels, TheDeviceSamplesAndLooksUpAsTheFloatCompilation) {
  environment_map e = test::sky_sun_map(30);
  e.strength = 0.5;
  e.visible = false;
  const std::vector<float> table = environment_table_of(e);
  const std::vector<std::uint32_t>& texels = e.image->texels;
  std::mt19937_64 rng(46);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  std::vector<gpu::environment_probe_entry> in(4096);
  for (gpu::environment_probe_entry& p : in) {
    p.ux = uniform(rng);
    p.uy = uniform(rng);
    const float z = 2 * uniform(rng) - 1, phi = 6.2831853f * uniform(rng);
    const float r = std::sqrt(std::max(0.0f, 1 - z * z));
    p.query = glm::vec3(r * std::cos(phi), z, r * std::sin(phi));
  }
  const std::vector<gpu::environment_probe_entry> out =
      gpu::run_environment_probe(gpu(), texels, table, in);
  ASSERT_EQ(out.size(), in.size());
  int radiance_differs = 0, query_differs = 0;
  double worst_wi = 0, worst_pdf = 0;
  for (std::size_t i = 0; i < in.size(); ++i) {
    gpu::environment_probe_entry cpu = in[i];
    f32::run_environment_probe(texels.data(), table.data(), cpu);
    const gpu::environment_probe_entry& g = out[i];
    ASSERT_EQ(g.trips, 15u);  // ceil(log2 256) + ceil(log2 128)
    ASSERT_EQ(g.trips, cpu.trips);
    ASSERT_EQ(g.visible, 0u);
    radiance_differs += g.radiance != cpu.radiance;
    worst_wi = std::max(worst_wi, double(glm::length(g.wi - cpu.wi)));
    worst_pdf = std::max(worst_pdf, std::abs(double(g.pdf) / cpu.pdf - 1));
    query_differs +=
        g.radiance_query != cpu.radiance_query || std::abs(double(g.pdf_query) - cpu.pdf_query) >
                                                      2e-3 * std::max(double(cpu.pdf_query), 1e-6);
  }
  EXPECT_EQ(radiance_differs, 0);
  EXPECT_LT(worst_wi, 2e-3);
  EXPECT_LT(worst_pdf, 2e-3);
  EXPECT_LE(query_differs, int(in.size()) / 100);
  std::cout << "worst direction gap " << worst_wi << ", density " << worst_pdf << ", "
            << query_differs << " of " << in.size() << " queries differ\n";
}

}  // namespace
}  // namespace rtvk
