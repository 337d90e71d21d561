#include "render_gpu.h"

#include "gpu_engine.h"

namespace rtvk::gpu {

std::uint32_t default_loop_budget(const device_info& d) {
  // By driver ID; a device too old to report one is known by its name.
  const bool llvmpipe = d.driver_id == VK_DRIVER_ID_MESA_LLVMPIPE ||
                        (d.driver_id == VkDriverId(0) && d.name.rfind("llvmpipe", 0) == 0);
  return llvmpipe ? 60'000u : 0xffffffffu;
}

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
