#pragma once
// The hardware ray-tracing paths (rt-query, rt-pipeline) against the compute BVH: a scene's exact
// sums through each traversal the device has, pixel by pixel (what GpuPbr, GpuEnvironment and
// GpuNee assert for their scenes; GpuHardwareRt has its own, with budgets).
#include <gtest/gtest.h>

#include "gpu_engine.h"
#include "render_helpers.h"

namespace rtvk::test {

// The scene's sums through traversal `t`.
inline gpu::sum_image traversal_sums(gpu::gpu_context& ctx, const scene& s, gpu_traversal t) {
  gpu::gpu_render_options o;
  o.engine.traversal = t;
  gpu::gpu_engine engine(ctx, s, o);
  const camera cam = scene_camera(s);
  return engine.render_sums({cam}, s.render,
                            whole_render(cam.image_width(), cam.image_height(), s.render.spp))[0];
}

// Pixels whose sums (channels, their top words, samples) differ between two renders.
inline int differing_sums(const gpu::sum_image& want, const gpu::sum_image& got) {
  EXPECT_EQ(got.pixels.size(), want.pixels.size());
  int differ = 0;
  for (std::size_t i = 0; i < want.pixels.size() && i < got.pixels.size(); ++i) {
    const gpu::pixel_sum& a = want.pixels[i];
    const gpu::pixel_sum& b = got.pixels[i];
    differ += a.r != b.r || a.g != b.g || a.b != b.b || a.r_top != b.r_top || a.g_top != b.g_top ||
              a.b_top != b.b_top || a.samples != b.samples;
  }
  return differ;
}

// Each hardware path the device has gives the compute BVH's exact sums for `s` (Mesa 22.3's
// lavapipe has neither: GpuHardwareRt checks the refusal there).
inline void expect_hardware_paths_match(gpu::gpu_context& ctx, const scene& s) {
  const gpu::sum_image want = traversal_sums(ctx, s, gpu_traversal::compute);
  for (gpu_traversal t : {gpu_traversal::ray_query, gpu_traversal::ray_pipeline}) {
    const bool has =
        t == gpu_traversal::ray_query ? ctx.ray_queries() : ctx.ray_tracing_pipelines();
    if (!has) continue;
    EXPECT_EQ(differing_sums(want, traversal_sums(ctx, s, t)), 0)
        << s.name << ", " << (t == gpu_traversal::ray_query ? "rt-query" : "rt-pipeline");
  }
}

}  // namespace rtvk::test
