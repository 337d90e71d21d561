#include "aov_pass.h"

#include <algorithm>
#include <cstring>

#include "packing.h"
#include "shaders.h"

namespace rtvk::gpu {

aov_pass::aov_pass(gpu_context& ctx, const gpu_scene& g, bool use_bvh)
    : ctx_(ctx),
      scene_(g),
      use_bvh_(use_bvh),
      camera_(ctx, sizeof(camera_ubo), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, memory_use::upload) {}

std::vector<buffer_binding> aov_pass::bindings() const {
  std::vector<buffer_binding> b = scene_.object_bindings();
  for (const buffer_binding& a : scene_.appearance_bindings()) b.push_back(a);
  b.push_back({RTVK_BINDING_MATERIALS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, scene_.materials()});
  b.push_back({RTVK_BINDING_CAMERA, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, camera_.get()});
  b.push_back({RTVK_BINDING_AOV, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, out_->get()});
  return b;
}

std::vector<gpu_aov> aov_pass::run(const camera& cam, const render_window& win) {
  // Bands of rows of at most 64 MiB: every Vulkan device binds 128 MiB of a storage buffer.
  const std::size_t row_bytes = std::size_t(win.width) * sizeof(gpu_aov);
  const int band = int(std::max<std::size_t>(
      1, std::min<std::size_t>(std::size_t(win.height), (std::size_t(64) << 20) / row_bytes)));
  const VkDeviceSize band_bytes = row_bytes * std::size_t(band);
  if (!out_ || out_->size() < band_bytes) {
    out_ = std::make_unique<gpu_buffer>(ctx_, band_bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                        memory_use::readback);  // host-cached: the host reads it
    if (pipeline_) pipeline_->rebind(bindings());
  }
  if (!pipeline_) {
    std::uint32_t spec[RTVK_SPEC_COUNT] = {};
    scene_.specialize(spec);
    spec[RTVK_SPEC_USE_BVH] = use_bvh_;
    pipeline_ = std::make_unique<compute_pipeline>(ctx_, aov_shader(), bindings(),
                                                   sizeof(render_push), spec);
  }
  const camera_ubo ubo = to_ubo(cam);
  camera_.write(&ubo, sizeof ubo);
  render_push push{};
  scene_.set_counts(push);
  // One ray an invocation. A traversal's trips are bounded by the tree (or the object count),
  // far inside lavapipe's 65,535 for any scene rtvk takes; no budget to pace.
  push.loop_budget = 0xffffffffu;
  push.region_x0 = std::uint32_t(win.x);
  push.region_width = std::uint32_t(win.width);
  std::vector<gpu_aov> result(std::size_t(win.width) * std::size_t(win.height));
  for (int row0 = 0; row0 < win.height; row0 += band) {
    const int rows = std::min(band, win.height - row0);
    push.band_y0 = std::uint32_t(win.y + row0);
    push.band_rows = std::uint32_t(rows);
    ctx_.submit_and_wait([&](VkCommandBuffer cb) {
      VkMemoryBarrier written{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
      written.srcAccessMask = VK_ACCESS_HOST_WRITE_BIT;
      written.dstAccessMask = VK_ACCESS_UNIFORM_READ_BIT;
      vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_HOST_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0,
                           1, &written, 0, nullptr, 0, nullptr);
      pipeline_->bind(cb);
      pipeline_->push(cb, &push, sizeof push);
      pipeline_->dispatch(cb,
                          {std::uint32_t((win.width + 7) / 8), std::uint32_t((rows + 7) / 8), 1});
      VkMemoryBarrier done{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
      done.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
      done.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
      vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0,
                           1, &done, 0, nullptr, 0, nullptr);
    });
    std::memcpy(result.data() + std::size_t(row0) * std::size_t(win.width), out_->read(),
                row_bytes * std::size_t(rows));
  }
  return result;
}

std::vector<gpu_aov> run_aov_pass(gpu_context& ctx, const scene& s, bool use_bvh, const camera& cam,
                                  const render_window& win) {
  const gpu_scene g(ctx, s, use_bvh);
  ctx.submit_and_wait([&](VkCommandBuffer cb) {
    g.record_upload(cb);
    VkMemoryBarrier upload{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    upload.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_HOST_WRITE_BIT;
    upload.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
    vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_HOST_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &upload, 0, nullptr, 0,
                         nullptr);
  });
  return aov_pass(ctx, g, use_bvh).run(cam, win);
}

}  // namespace rtvk::gpu
