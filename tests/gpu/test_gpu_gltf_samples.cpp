// The Khronos glTF feature-test models on the device (tests/gltf_samples.h): each view's image
// within the Monte Carlo rule of the CPU's (rtvk render --backend both's), and through the same
// README checks as tests/scene/test_gltf_samples.cpp holds the CPU's to.
#include <gtest/gtest.h>

#include "gltf_samples.h"
#include "gpu_fixture.h"

namespace rtvk {
namespace {

class GpuGltfSamples : public test::GpuTest {};

TEST_F(GpuGltfSamples, EachFeatureTestModelMatchesTheCpuAndPassesItsReadmesChecks) {
  for (const test::sample_case& c : test::sample_cases())
    for (std::size_t k = 0; k < c.views.size(); ++k) {
      const test::sample_view& v = c.views[k];
      const camera cam = test::scene_camera(v.s);
      const framebuffer cpu = render_cpu(cam, v.s, v.s.render);
      const framebuffer dev = gpu::render_gpu(gpu(), cam, v.s, v.s.render);
      const image_difference d =
          compare_images(quantize(dev, v.s.render.encoding()), quantize(cpu, v.s.render.encoding()),
                         monte_carlo_agreement.tolerance);
      EXPECT_TRUE(agrees(d, monte_carlo_agreement))
          << c.name << ", view " << k << ": " << d.share_over * 100 << "% of pixels over "
          << monte_carlo_agreement.tolerance << " levels, PSNR " << d.psnr_db << " dB";
      EXPECT_EQ(c.check(v, dev), "") << c.name << ", view " << k << " (device)";
    }
}

}  // namespace
}  // namespace rtvk
