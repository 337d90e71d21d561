#include "render_gpu.h"

#include "gpu_engine.h"

namespace rtvk::gpu {

framebuffer render_gpu(gpu_context& ctx, const camera& cam, const scene& s,
                       const render_settings& rs, const sample_progress& progress,
                       const gpu_render_options& options, render_stats* stats) {
  return std::move(render_gpu_views(ctx, {cam}, s, rs,
                                    whole_render(cam.image_width(), cam.image_height(), rs.spp),
                                    progress, options, stats)
                       .front());
}

std::vector<framebuffer> render_gpu_views(gpu_context& ctx, const std::vector<camera>& views,
                                          const scene& s, const render_settings& rs,
                                          const render_window& win, const sample_progress& progress,
                                          const gpu_render_options& options, render_stats* stats) {
  gpu_engine engine(ctx, s, options);
  return engine.render_views(views, rs, win, progress, stats);
}

}  // namespace rtvk::gpu
