#pragma once
#include <cstdint>
#include <vector>

#include "buffer.h"
#include "context.h"
#include "device_fit.h"

namespace rtvk::gpu {

// Where one group of views draws a band of rows: the camera block, the float sums the dispatches
// accumulate into, the per-pixel ray counters, the status block that reports loop-budget
// overruns, and host-visible copies to read the sums and counters back.
struct render_targets {
  // `image_bytes`: the largest band's sums; `count_bytes`: its ray counters (4 when not counted).
  render_targets(const gpu_context& ctx, VkDeviceSize image_bytes, VkDeviceSize count_bytes);

  // The buffers a render allocates, the scene's in between, in the order check_device_fits
  // reports them.
  static std::vector<buffer_request> buffers(const std::vector<buffer_request>& scene_buffers,
                                             VkDeviceSize image_bytes, VkDeviceSize count_bytes);

  gpu_buffer cameras;       // camera_ubo per view of the group (uniform)
  gpu_buffer ray_counts;    // one counter per pixel (storage)
  gpu_buffer ray_readback;  // ray_counts, copied back
  gpu_buffer image;         // RGB float sums per pixel (storage)
  gpu_buffer readback;      // image, copied back
  gpu_buffer status;        // render_status (storage, host-visible)
};

}  // namespace rtvk::gpu
