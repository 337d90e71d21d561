#include "render_targets.h"

#include "shared_types.h"

namespace rtvk::gpu {
namespace {

constexpr VkBufferUsageFlags storage_copy = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                            VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                            VK_BUFFER_USAGE_TRANSFER_DST_BIT;
constexpr VkDeviceSize camera_bytes = RTVK_MAX_VIEWS * sizeof(camera_ubo);
constexpr VkDeviceSize threshold_bytes = 256 * sizeof(uvec2);

}  // namespace

render_targets::render_targets(const gpu_context& ctx, VkDeviceSize pixels)
    : pixels(pixels),
      cameras(ctx, camera_bytes, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, memory_use::upload),
      sums(ctx, pixels * sizeof(pixel_sum), storage_copy, memory_use::device_local),
      bytes(ctx, pixels * 4, storage_copy, memory_use::device_local),
      thresholds(ctx, threshold_bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, memory_use::upload),
      readback(ctx, pixels * sizeof(pixel_sum), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
               memory_use::readback),
      status(ctx, sizeof(render_status),
             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
             memory_use::readback) {}

std::vector<buffer_request> render_targets::buffers(
    const std::vector<buffer_request>& scene_buffers, VkDeviceSize pixels) {
  using u = memory_use;
  std::vector<buffer_request> out{{"the camera block", camera_bytes, false, u::upload}};
  out.insert(out.end(), scene_buffers.begin(), scene_buffers.end());
  out.insert(out.end(),
             {{"the image band's sums", pixels * sizeof(pixel_sum), true, u::device_local},
              {"the image band's bytes", pixels * 4, true, u::device_local},
              {"the byte thresholds", threshold_bytes, true, u::upload},
              {"the image band's readback", pixels * sizeof(pixel_sum), false, u::readback},
              {"the status block", sizeof(render_status), true, u::readback}});
  return out;
}

}  // namespace rtvk::gpu
