#include "render_targets.h"

#include "shared_types.h"

namespace rtvk::gpu {
namespace {

constexpr VkBufferUsageFlags storage_copy = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                            VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                            VK_BUFFER_USAGE_TRANSFER_DST_BIT;
constexpr VkDeviceSize camera_bytes = RTVK_MAX_VIEWS * sizeof(camera_ubo);
constexpr VkDeviceSize threshold_bytes = 256 * sizeof(uvec2);

// The readback, then a status readback per submission in flight.
std::vector<buffer_spec> host_specs(VkDeviceSize pixels) {
  std::vector<buffer_spec> specs{{pixels * sizeof(pixel_sum), VK_BUFFER_USAGE_TRANSFER_DST_BIT}};
  for (std::uint64_t k = 0; k < gpu_context::submission_slots; ++k)
    specs.push_back({sizeof(render_status), VK_BUFFER_USAGE_TRANSFER_DST_BIT});
  return specs;
}

// Allocation numbers for check_device_fits (the scene's sets use others).
enum : int { device_set = 100, host_set };

}  // namespace

render_targets::render_targets(const gpu_context& ctx, VkDeviceSize pixels)
    : pixels(pixels),
      device_(ctx, memory_use::device_local,
              std::vector<buffer_spec>{{pixels * sizeof(pixel_sum), storage_copy},
                                       {pixels * 4, storage_copy, true},  // the viewer shows them
                                       {camera_bytes, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT |
                                                          VK_BUFFER_USAGE_TRANSFER_DST_BIT},
                                       {threshold_bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                                             VK_BUFFER_USAGE_TRANSFER_DST_BIT},
                                       {sizeof(render_status), storage_copy}}),
      host_(ctx, memory_use::readback, host_specs(pixels)),
      cameras(device_[2]),
      sums(device_[0]),
      bytes(device_[1]),
      thresholds(device_[3]),
      status(device_[4]),
      readback(host_[0]) {}

std::vector<buffer_request> render_targets::buffers(
    const std::vector<buffer_request>& scene_buffers, VkDeviceSize pixels) {
  using u = memory_use;
  std::vector<buffer_request> out{
      {"the camera block", camera_bytes, false, u::device_local, device_set}};
  out.insert(out.end(), scene_buffers.begin(), scene_buffers.end());
  out.insert(
      out.end(),
      {{"the image band's sums", pixels * sizeof(pixel_sum), true, u::device_local, device_set},
       {"the image band's bytes", pixels * 4, true, u::device_local, device_set},
       {"the byte thresholds", threshold_bytes, true, u::device_local, device_set},
       {"the status block", sizeof(render_status), true, u::device_local, device_set},
       {"the image band's readback", pixels * sizeof(pixel_sum), false, u::readback, host_set},
       {"the status block's readbacks", gpu_context::submission_slots * sizeof(render_status),
        false, u::readback, host_set}});
  return out;
}

}  // namespace rtvk::gpu
