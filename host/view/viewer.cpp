#include "viewer.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <memory>
#include <vector>

#include "byte_encoding.h"
#include "elapsed.h"
#include "gpu_engine.h"
#include "parallel.h"
#include "presenter.h"
#include "swapchain.h"
#include "vk_error.h"
#include "window.h"

namespace rtvk::view {
namespace {

// Exact per-pixel sums of every batch so far: integer additions, so the result does not depend
// on how the samples were batched (the same bits as one render of all of them).
struct accumulation {
  int width = 0, height = 0;        // pixels
  int samples = 0;                  // per pixel, all pixels alike
  std::vector<std::uint64_t> sums;  // 3 per pixel: r, g, b

  void reset(int w, int h) {
    width = w;
    height = h;
    samples = 0;
    sums.assign(std::size_t(w) * std::size_t(h) * 3, 0);
  }
  void add(const gpu::sum_image& batch, int batch_samples) {
    const auto word = [](gpu::uvec2 v) { return std::uint64_t(v.y) << 32 | v.x; };
    parallel_for(batch.pixels.size(), 0, 4096, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        sums[3 * i] += word(batch.pixels[i].r);
        sums[3 * i + 1] += word(batch.pixels[i].g);
        sums[3 * i + 2] += word(batch.pixels[i].b);
      }
    });
    samples += batch_samples;
  }
};

// The running mean as 8-bit RGB (for screenshots) and RGBA (for the window), by encode_sum: the
// device's tonemap.comp encodes rtvk render's images bit for bit the same way.
void encode(const accumulation& acc, const byte_thresholds& t, image_rgb8& rgb,
            std::vector<std::uint32_t>& rgba) {
  const std::size_t pixels = std::size_t(acc.width) * std::size_t(acc.height);
  rgb.width = acc.width;
  rgb.height = acc.height;
  rgb.rgb.resize(pixels * 3);
  rgba.resize(pixels);
  parallel_for(pixels, 0, 4096, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      std::uint32_t packed = 0xff000000u;
      for (int c = 0; c < 3; ++c) {
        const std::uint8_t byte = encode_sum(acc.sums[3 * i + c], std::uint32_t(acc.samples), t);
        rgb.rgb[3 * i + c] = byte;
        packed |= std::uint32_t(byte) << (8 * c);
      }
      rgba[i] = packed;
    }
  });
}

// Samples per batch: grown or shrunk so a batch takes about a tenth of a second, which keeps
// the window responsive (about 10 frames a second) on slow devices and busy on fast ones.
int next_batch(int batch, double seconds) {
  constexpr double target = 0.1;
  if (seconds < target / 2) return std::min(batch * 2, 1 << 16);
  if (seconds > target * 2) return std::max(batch / 2, 1);
  return batch;
}

}  // namespace

viewer_result run_viewer(const scene& s, const camera_pose& pose, const viewer_options& options) {
  const window_system windowing;
  const int start_w = options.size_follows_window ? 960 : s.render.width;
  const int start_h =
      options.size_follows_window ? 540 : std::max(1, int(s.render.width / s.render.aspect));
  window win(windowing, start_w, start_h, "rtvk view: " + s.name);
  gpu::gpu_options gpu = options.gpu;
  gpu.instance_extensions = windowing.instance_extensions();
  gpu.make_surface = [&](VkInstance instance) { return win.create_surface(instance); };
  gpu::gpu_context ctx(gpu);
  gpu::gpu_engine engine(ctx, s, options.render);
  const byte_thresholds thresholds = make_byte_thresholds(s.render.gamma, engine.sum_exponent());

  int fb_w = 0, fb_h = 0;
  win.framebuffer_size(fb_w, fb_h);
  swapchain chain(ctx, std::max(fb_w, 1), std::max(fb_h, 1));
  render_settings rs = s.render;
  accumulation acc;
  std::unique_ptr<presenter> shown;
  gpu::unique_semaphore acquired;
  {
    VkSemaphoreCreateInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore sem = VK_NULL_HANDLE;
    gpu::vk_check(vkCreateSemaphore(ctx.vk(), &info, nullptr, &sem), "vkCreateSemaphore");
    acquired = gpu::unique_semaphore(ctx.vk(), sem);
  }
  viewer_result result;
  result.pose = pose;
  image_rgb8 rgb;
  std::vector<std::uint32_t> rgba;
  int batch = 1;
  bool resized = true;
  while (!win.should_close() && !(options.cancelled && options.cancelled())) {
    win.poll();
    win.framebuffer_size(fb_w, fb_h);
    if (fb_w == 0 || fb_h == 0) {  // minimized: nothing to show, nothing to render
      win.wait();
      continue;
    }
    if (resized || (options.size_follows_window && (fb_w != acc.width || fb_h != acc.height))) {
      if (options.size_follows_window) {
        rs.width = fb_w;
        rs.aspect = double(fb_w) / double(fb_h);
      }
      const camera cam_for_size(pose, rs.aspect, rs.width);
      acc.reset(cam_for_size.image_width(), cam_for_size.image_height());
      shown = std::make_unique<presenter>(ctx, acc.width, acc.height);
      if (chain.extent().width != std::uint32_t(fb_w) ||
          chain.extent().height != std::uint32_t(fb_h))
        chain.recreate(fb_w, fb_h);
      resized = false;
    }
    const bool want_more = options.target_spp == 0 || acc.samples < options.target_spp;
    if (want_more) {
      const camera cam(pose, rs.aspect, rs.width);
      const int count =
          options.target_spp == 0 ? batch : std::min(batch, options.target_spp - acc.samples);
      const render_window window{0, 0, acc.width, acc.height, acc.samples, acc.samples + count};
      const auto start = std::chrono::steady_clock::now();
      const std::vector<gpu::sum_image> sums = engine.render_sums({cam}, rs, window);
      acc.add(sums.front(), count);
      batch = next_batch(batch, seconds_since(start));
      encode(acc, thresholds, rgb, rgba);
      shown->write(rgba.data());
    }
    std::uint32_t index = 0;
    if (!chain.acquire(acquired.get(), index)) {
      chain.recreate(fb_w, fb_h);
      continue;
    }
    const std::uint64_t ticket =
        ctx.submit([&](VkCommandBuffer cb) { shown->record(cb, chain, index); },
                   gpu::submit_sync{acquired.get(), VK_PIPELINE_STAGE_TRANSFER_BIT,
                                    chain.ready_to_present(index)});
    ctx.wait(ticket);
    if (!chain.present(index)) chain.recreate(fb_w, fb_h);
    if (!want_more) {
      if (options.exit_at_target) break;
      win.wait();  // done accumulating: idle until something happens
    }
  }
  ctx.wait_all();
  vkDeviceWaitIdle(ctx.vk());
  result.width = acc.width;
  result.aspect = rs.aspect;
  result.height = acc.height;
  result.samples = acc.samples;
  result.image = std::move(rgb);
  if (ctx.validation_messages() > 0)
    throw std::runtime_error("the Vulkan validation layer reported " +
                             std::to_string(ctx.validation_messages()) + " problem(s) (above)");
  return result;
}

}  // namespace rtvk::view
