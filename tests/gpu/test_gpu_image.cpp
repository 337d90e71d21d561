// The GPU port draws the CPU reference's picture.
#include <gtest/gtest.h>

#include <tuple>

#include "gpu_fixture.h"
#include "image_compare.h"
#include "quantize.h"
#include "render_cpu.h"
#include "render_gpu.h"
#include "render_helpers.h"

namespace rtvk {
namespace {

class GpuImage : public test::GpuTest {};

// An aspect ratio whose derived height is exactly h at width w.
double aspect_for(int w, int h) {
  return w / (h + 0.5);
}

TEST_F(GpuImage, SeedMatchesTheCpuReference) {
  const scene s = builtin_scene("seed");
  for (auto [w, h] : {std::tuple{400, 225}, {1, 1}, {7, 3}, {333, 101}, {64, 1}, {1, 64}}) {
    SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h));
    const camera cam(aspect_for(w, h), w);
    ASSERT_EQ(cam.image_height(), h);
    const image_rgb8 cpu = test::cpu_image(s, cam);
    const image_rgb8 gpu_img = test::gpu_image(gpu(), s, cam);
    ASSERT_EQ(gpu_img.width, w);
    ASSERT_EQ(gpu_img.height, h);
    const image_difference d = compare_images(gpu_img, cpu, 1);
    EXPECT_LE(d.share_over, 0.001) << d.pixels_over << " pixels differ by more than 1 level";
    EXPECT_LT(d.mean_abs, 0.1) << "mean absolute difference, levels";
  }
}

TEST_F(GpuImage, EmptySceneIsAllSky) {
  scene empty = builtin_scene("seed");
  empty.spheres.clear();
  const camera cam(2.0, 50);
  const image_rgb8 cpu = test::cpu_image(empty, cam);
  const image_rgb8 gpu_img = test::gpu_image(gpu(), empty, cam);
  EXPECT_LE(compare_images(gpu_img, cpu, 1).max_abs, 1);
}

TEST_F(GpuImage, SceneChangesReachTheGpu) {
  // A moved sphere must move in the GPU image too: guards against stale or ignored buffers.
  scene s = builtin_scene("seed");
  const camera cam(2.0, 80);
  const image_rgb8 before = test::gpu_image(gpu(), s, cam);
  s.spheres[0].center.x += 0.5;
  const image_rgb8 after = test::gpu_image(gpu(), s, cam);
  EXPECT_GT(compare_images(before, after, 1).pixels_over, 100);
  EXPECT_LE(compare_images(after, test::cpu_image(s, cam), 1).share_over, 0.001);
}

}  // namespace
}  // namespace rtvk
