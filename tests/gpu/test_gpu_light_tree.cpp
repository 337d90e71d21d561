// The light tree on the GPU (shaders/shared/lights/light_tree.h at RTVK_BINDING_LIGHT_TREE): a
// scene of many small lamps and lamps placed by instances, under next-event estimation, draws the
// CPU's image by the rule GpuBook's scenes follow (tests/cpu/test_light_tree.cpp checks the tree
// itself and that both converge to the plain image).
#include <gtest/gtest.h>

#include <random>

#include "gpu/kernels_f32.h"
#include "gpu_fixture.h"
#include "hardware_sums.h"
#include "image_compare.h"
#include "light_sources.h"
#include "light_tree_builder.h"
#include "light_tree_scenes.h"
#include "nee.h"
#include "packing.h"
#include "probe.h"
#include "render_gpu.h"
#include "render_helpers.h"

namespace rtvk {
namespace {

class GpuLightTree : public test::GpuTest {
 protected:
  GpuLightTree() { ray_tracing_ = true; }
};

// A thousand lamps (triangles, spheres, quads) and, in the same room, the instanced group of
// lamps, under next-event estimation.
scene lamps_and_instances(int width, int spp) {
  scene s = test::many_lamps(1000, true, width, spp);
  const scene grouped = test::grouped_lamps(width);
  const int offset = int(s.materials.size());
  for (const named_material& m : grouped.materials) s.materials.push_back(m);
  for (object_group g : grouped.groups) {
    for (sphere& sp : g.spheres) sp.material += offset;
    for (quad& q : g.quads) q.material += offset;
    s.groups.push_back(g);
  }
  s.instances = grouped.instances;
  s.render.sampling = sampling_mode::nee;
  return s;
}

// Both scenes in one render, one shader variant. Measured on lavapipe 22.3 (2026-11-28): 61.8 dB,
// one pixel of 576 more than 2 levels off (the float descent takes another lamp where two
// children's importances nearly tie, the double one the other).
TEST_F(GpuLightTree, ManyLampsAndInstancedOnesMatchTheCpu) {
  const scene s = lamps_and_instances(24, 8);
  const image_rgb8 cpu = test::cpu_image(s);
  const image_difference d =
      compare_images(test::gpu_image(gpu(), s), cpu, monte_carlo_agreement.tolerance);
  std::printf("PSNR %.2f dB, %ld pixels over\n", d.psnr_db, long(d.pixels_over));
  const agreement rule = test::measured_agreement(61.8, 1.0 / 576, cpu.width * cpu.height);
  EXPECT_GE(d.psnr_db, rule.min_psnr_db);
  EXPECT_LE(d.share_over, rule.max_share) << d.pixels_over << " pixels over 2 levels";
}

// The hardware paths (Mesa 25) draw the same lamps through the same tree and find the same lamp
// hits in world space, instanced ones included: the compute BVH's sums exactly.
TEST_F(GpuLightTree, TheHardwarePathsGiveTheComputeBvhsExactSums) {
  test::expect_hardware_paths_match(gpu(), lamps_and_instances(16, 2));
}

// The device's draw, point query and trail (light_tree_probe.comp) against the float
// compilation's, on 300 lamps from 2,000 random points, each with a ray to a point drawn on some
// lamp: the same lamp drawn and the same leaf found, their probabilities within 1e-4 relative
// (measured on lavapipe 22.3 and Mesa 25: every entry the same, the probabilities equal).
TEST_F(GpuLightTree, TheDeviceDrawsAndFindsAsTheFloatCompilation) {
  const std::vector<light_record> records = scene_lamps(test::many_lamps(300, true, 8, 1));
  const std::vector<gpu::gpu_light> lamps = gpu::to_gpu_lights(records);
  const std::vector<gpu::gpu_light_node> nodes = build_light_tree(records);
  std::mt19937_64 gen(5);
  std::uniform_real_distribution<double> place(-50, 600), dir(-1, 1), u(0, 1);
  std::vector<gpu::light_tree_probe_entry> in(2000);
  for (std::size_t i = 0; i < in.size(); ++i) {
    gpu::light_tree_probe_entry& e = in[i];
    const point3 p(place(gen), place(gen), place(gen));
    e.p = glm::vec3(p);
    e.n = i % 4 == 3 ? glm::vec3(0) : glm::normalize(glm::vec3(dir(gen), dir(gen), dir(gen)));
    e.u = float(u(gen));
    const light_sample ls = lamp_sample(records[i % records.size()], p, 0, u(gen), u(gen));
    e.d = ls.pdf > 0 ? glm::vec3(ls.wi) : glm::vec3(0, 1, 0);
    e.t_hit = ls.pdf > 0 ? float(ls.distance) : 1.0f;
  }
  const std::vector<gpu::light_tree_probe_entry> out =
      gpu::run_light_tree_probe(gpu(), lamps, nodes, in);
  ASSERT_EQ(out.size(), in.size());
  int found = 0;
  double worst = 0;
  for (std::size_t i = 0; i < in.size(); ++i) {
    gpu::light_tree_probe_entry want = in[i];
    f32::run_light_tree_probe(lamps, nodes, want);
    const gpu::light_tree_probe_entry& got = out[i];
    ASSERT_EQ(got.lamp, want.lamp) << "entry " << i;
    EXPECT_NEAR(got.pmf, want.pmf, 1e-4 * want.pmf) << "entry " << i;
    ASSERT_EQ(got.found, want.found) << "entry " << i;
    if (want.found == 0u) continue;
    ++found;
    ASSERT_EQ(got.leaf, want.leaf) << "entry " << i;
    EXPECT_NEAR(got.leaf_pmf, want.leaf_pmf, 1e-4 * want.leaf_pmf) << "entry " << i;
    worst = std::max(worst, double(std::abs(got.pmf - want.pmf) / want.pmf));
    if (want.leaf_pmf > 0)
      worst = std::max(worst, double(std::abs(got.leaf_pmf - want.leaf_pmf) / want.leaf_pmf));
  }
  std::printf("%d of %zu rays found their lamp; worst relative difference %.3g\n", found, in.size(),
              worst);
  EXPECT_GT(found, 1400);  // 1,534 (the rest drew no point, or another lamp lies in front)
}

}  // namespace
}  // namespace rtvk
