#include "aov_pass.h"

#include <algorithm>
#include <cstring>

#include "buffer.h"
#include "compute_pipeline.h"
#include "gpu_scene.h"
#include "packing.h"
#include "shaders.h"

namespace rtvk::gpu {

std::vector<gpu_aov> run_aov_pass(gpu_context& ctx, const scene& s, bool use_bvh, const camera& cam,
                                  const render_window& win) {
  const gpu_scene g(ctx, s, use_bvh);
  // Bands of rows of at most 64 MiB: every Vulkan device binds 128 MiB of a storage buffer.
  const std::size_t row_bytes = std::size_t(win.width) * sizeof(gpu_aov);
  const int band = int(std::max<std::size_t>(
      1, std::min<std::size_t>(std::size_t(win.height), (std::size_t(64) << 20) / row_bytes)));
  gpu_buffer out(ctx, row_bytes * std::size_t(band), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                 memory_use::readback);  // host-cached where it can be: the host reads it all
  const camera_ubo ubo = to_ubo(cam);
  gpu_buffer camera_buffer(ctx, sizeof ubo, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, memory_use::upload);
  camera_buffer.write(&ubo, sizeof ubo);
  std::uint32_t spec[RTVK_SPEC_COUNT] = {};
  g.specialize(spec);
  spec[RTVK_SPEC_USE_BVH] = use_bvh;
  std::vector<buffer_binding> bindings = g.object_bindings();
  for (const buffer_binding& b : g.appearance_bindings()) bindings.push_back(b);
  bindings.push_back({RTVK_BINDING_MATERIALS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, g.materials()});
  bindings.push_back({RTVK_BINDING_CAMERA, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, camera_buffer.get()});
  bindings.push_back({RTVK_BINDING_AOV, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, out.get()});
  const compute_pipeline pipeline(ctx, aov_shader(), bindings, sizeof(render_push), spec);
  render_push push{};
  g.set_counts(push);
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
    ctx.submit_and_wait([&](VkCommandBuffer cb) {
      if (row0 == 0) g.record_upload(cb);
      VkMemoryBarrier upload{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
      upload.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_HOST_WRITE_BIT;
      upload.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_UNIFORM_READ_BIT;
      vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_HOST_BIT,
                           VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &upload, 0, nullptr, 0,
                           nullptr);
      pipeline.bind(cb);
      pipeline.push(cb, &push, sizeof push);
      pipeline.dispatch(cb, {std::uint32_t((win.width + 7) / 8), std::uint32_t((rows + 7) / 8), 1});
      VkMemoryBarrier done{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
      done.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
      done.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
      vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0,
                           1, &done, 0, nullptr, 0, nullptr);
    });
    std::memcpy(result.data() + std::size_t(row0) * std::size_t(win.width), out.read(),
                row_bytes * std::size_t(rows));
  }
  return result;
}

}  // namespace rtvk::gpu
