#include "render_targets.h"

#include "shared_types.h"

namespace rtvk::gpu {
namespace {

constexpr VkBufferUsageFlags storage_copy = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                            VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                            VK_BUFFER_USAGE_TRANSFER_DST_BIT;
constexpr VkDeviceSize camera_bytes = RTVK_MAX_VIEWS * sizeof(camera_ubo);

}  // namespace

render_targets::render_targets(const gpu_context& ctx, VkDeviceSize image_bytes,
                               VkDeviceSize count_bytes)
    : cameras(ctx, camera_bytes, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, memory_use::upload),
      ray_counts(ctx, count_bytes, storage_copy, memory_use::device_local),
      ray_readback(ctx, count_bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, memory_use::readback),
      image(ctx, image_bytes, storage_copy, memory_use::device_local),
      readback(ctx, image_bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, memory_use::readback),
      status(ctx, sizeof(render_status),
             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
             memory_use::readback) {}

std::vector<buffer_request> render_targets::buffers(
    const std::vector<buffer_request>& scene_buffers, VkDeviceSize image_bytes,
    VkDeviceSize count_bytes) {
  using u = memory_use;
  std::vector<buffer_request> out{{"the camera block", camera_bytes, false, u::upload}};
  out.insert(out.end(), scene_buffers.begin(), scene_buffers.end());
  out.insert(out.end(), {{"the ray counters", count_bytes, true, u::device_local},
                         {"the ray counters' readback", count_bytes, false, u::readback},
                         {"the image band", image_bytes, true, u::device_local},
                         {"the image band's readback", image_bytes, false, u::readback},
                         {"the status block", sizeof(render_status), true, u::readback}});
  return out;
}

}  // namespace rtvk::gpu
