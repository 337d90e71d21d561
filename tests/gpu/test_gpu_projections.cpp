// Every camera model on the GPU draws the CPU's picture: the lesson's scene (one sample, normal
// shading: deterministic), a posed Monte Carlo view of book-final, and a keyframed fisheye path.
#include <gtest/gtest.h>

#include "camera_path.h"
#include "gpu_fixture.h"
#include "image_compare.h"
#include "render_gpu.h"
#include "render_helpers.h"

namespace rtvk {
namespace {

class GpuProjections : public test::GpuTest {};

const projection all_models[] = {projection::perspective, projection::orthographic,
                                 projection::equirectangular, projection::fisheye_equidistant,
                                 projection::fisheye_equisolid};

TEST_F(GpuProjections, TheLessonsSceneMatchesTheCpuUnderEveryModel) {
  const scene s = builtin_scene("seed");
  for (projection p : all_models) {
    SCOPED_TRACE(std::string(projection_name(p)));
    camera_pose pose;
    pose.projection = p;
    pose.fisheye_fov = 200;
    const camera c(pose, 2, 240);
    const image_rgb8 on_gpu = test::gpu_image(gpu(), s, c), on_cpu = test::cpu_image(s, c);
    const image_difference d = compare_images(on_gpu, on_cpu, 1);
    EXPECT_TRUE(agrees(d, agreement{})) << d.share_over * 100 << "% of pixels over 1 level";
    if (p == projection::fisheye_equidistant || p == projection::fisheye_equisolid) {
      // Outside the circle: exactly black on both, no ray traced.
      for (const image_rgb8* img : {&on_gpu, &on_cpu})
        for (int k = 0; k < 3; ++k) EXPECT_EQ(img->pixel(0, 0)[k], 0);
    }
  }
}

TEST_F(GpuProjections, APosedMonteCarloViewMatchesTheCpuUnderEveryModel) {
  scene s = test::small_scene("book-final", 96, 8);
  s.render.max_depth = 10;
  camera_pose pose = main_camera(s).pose;
  pose.aperture = 0;  // the panoramic models have no lens
  for (projection p : all_models) {
    SCOPED_TRACE(std::string(projection_name(p)));
    pose.projection = p;
    const camera c(pose, 2, 96);
    const image_difference d = compare_images(test::gpu_image(gpu(), s, c), test::cpu_image(s, c),
                                              monte_carlo_agreement.tolerance);
    EXPECT_TRUE(agrees(d, monte_carlo_agreement))
        << "PSNR " << d.psnr_db << ", " << d.share_over * 100 << "% over 2 levels";
  }
}

TEST_F(GpuProjections, AKeyframedFisheyePathRendersAlikeOnBothBackends) {
  scene s = builtin_scene("seed");
  camera_path path;
  path.motion = camera_motion::keyframes;
  camera_pose a, b;
  a.projection = b.projection = projection::fisheye_equisolid;
  a.fisheye_fov = 150;
  b.fisheye_fov = 300;
  b.lookfrom = point3(0.3, 0.4, 0.2);
  path.keyframes = {{0.0, a}, {1.0, b}};
  std::vector<camera> views;
  for (double time : {0.0, 0.4, 1.0}) views.emplace_back(path.at(time), 16.0 / 9.0, 160);
  const render_window all = whole_render(160, views[0].image_height(), 1);
  const std::vector<framebuffer> fbs = gpu::render_gpu_views(gpu(), views, s, s.render, all);
  for (std::size_t k = 0; k < views.size(); ++k) {
    const image_difference d =
        compare_images(quantize(fbs[k], s.render.gamma), test::cpu_image(s, views[k]), 1);
    EXPECT_TRUE(agrees(d, agreement{})) << "view " << k;
  }
  // The field of view is interpolated, the model held.
  EXPECT_EQ(path.at(0.5).projection, projection::fisheye_equisolid);
  EXPECT_DOUBLE_EQ(path.at(0.5).fisheye_fov, 225);
}

}  // namespace
}  // namespace rtvk
