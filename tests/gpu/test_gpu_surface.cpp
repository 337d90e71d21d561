// The surface features beyond the books on the GPU (compute BVH and --accel none) against the
// CPU reference: emission (its texture on a second uv set), vertex colors, alpha mask and blend,
// back-face culling
// (tests/surface_scenes.h; their known answers are tests/cpu/test_surface.cpp's). Both backends
// draw the same random numbers, so even the blend's stochastic passes agree pixel for pixel; the
// bound (1e-5) is float's rounding of the colors and the vertex colors' blend.
#include <gtest/gtest.h>

#include <cmath>

#include "aov_pass.h"
#include "gpu_fixture.h"
#include "render_aov.h"
#include "render_gpu.h"
#include "render_helpers.h"
#include "surface_scenes.h"

namespace rtvk {
namespace {

class GpuSurface : public test::GpuTest {
 protected:
  // Pixels of the GPU's image (through the BVH or the scan) more than 1e-5 off the CPU's.
  int differing(const scene& s, bool use_bvh) {
    const camera cam = test::scene_camera(s);
    const framebuffer want = render_cpu(cam, s, s.render);
    gpu::gpu_render_options o;
    o.engine.use_bvh = use_bvh;
    const framebuffer got = gpu::render_gpu(gpu(), cam, s, s.render, {}, o);
    int differ = 0;
    for (int y = 0; y < want.height(); ++y)
      for (int x = 0; x < want.width(); ++x)
        for (int c = 0; c < 3; ++c) differ += std::abs(got.at(x, y)[c] - want.at(x, y)[c]) > 1e-5;
    return differ;
  }
  void expect_agreement(const scene& s, const char* what) {
    EXPECT_EQ(differing(s, true), 0) << what << ", bvh";
    EXPECT_EQ(differing(s, false), 0) << what << ", none";
  }
};

TEST_F(GpuSurface, EmissionVertexColorsAlphaAndCullingMatchTheCpu) {
  material emissive = test::flat_material(color(0.125, 0.25, 0.375));
  emissive.emission = color(0.5, 0.25, 2.0);
  scene textured = test::surface_scene(emissive, test::flat_material(color(0)));
  textured.textures.push_back(test::row_texture({0xff000000u | 51u | (102u << 8), 0xffffffffu}));
  textured.materials[0].m.emission_texture = 0;
  expect_agreement(textured, "emission");

  expect_agreement(test::vertex_color_scene(), "vertex colors");
  expect_agreement(test::second_uv_scene(), "second texture coordinates");

  material mask = test::flat_material(color(1));
  mask.alpha = alpha_mode::mask;
  mask.texture = 0;
  scene masked = test::surface_scene(mask, test::flat_material(color(0, 0, 1)));
  masked.textures.push_back(test::row_texture({0x000000ffu, 0xff00ff00u}));
  expect_agreement(masked, "mask");

  material blend = test::flat_material(color(1, 0, 0));
  blend.alpha = alpha_mode::blend;
  blend.opacity = 0.25;
  scene blended = test::surface_scene(blend, test::flat_material(color(0, 0, 1)));
  blended.render.spp = 64;
  expect_agreement(blended, "blend");

  material culled = test::flat_material(color(1, 0, 0));
  culled.cull_back = true;
  expect_agreement(test::surface_scene(culled, test::flat_material(color(0, 0, 1)), true),
                   "cull_back");
}

// The device's AOVs see the first surface that counts as the CPU's do: through a mask's clear
// half the back quad (object 1), through its opaque half the front (object 0), the same depths.
TEST_F(GpuSurface, TheAovsSeeTheFirstSurfaceThatCountsAsOnTheCpu) {
  material mask = test::flat_material(color(1));
  mask.alpha = alpha_mode::mask;
  mask.texture = 0;
  scene s = test::surface_scene(mask, test::flat_material(color(0, 0, 1)));
  s.textures.push_back(test::row_texture({0x000000ffu, 0xff00ff00u}));
  const camera cam = test::scene_camera(s);
  const render_window win{0, 0, 16, 16, 0, 1};
  const std::vector<gpu::gpu_aov> cpu = render_aov_cpu(cam, s, win);
  const std::vector<gpu::gpu_aov> dev = gpu::run_aov_pass(gpu(), s, true, cam, win);
  ASSERT_EQ(dev.size(), cpu.size());
  int differ = 0;
  for (std::size_t i = 0; i < cpu.size(); ++i)
    differ += dev[i].object != cpu[i].object || std::abs(dev[i].depth - cpu[i].depth) > 1e-5f;
  EXPECT_EQ(differ, 0);
  EXPECT_EQ(dev[8 * 16 + 2].object, 1u);
  EXPECT_EQ(dev[8 * 16 + 13].object, 0u);
}

}  // namespace
}  // namespace rtvk
