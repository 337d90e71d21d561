#pragma once
#include <cstdint>
#include <vector>

#include "buffer.h"
#include "context.h"
#include "device_fit.h"

namespace rtvk::gpu {

// Where one group of views draws a band of rows, all in device-local memory: the camera block,
// the exact sums the dispatches accumulate into (pixel_sum), the 8-bit pixels tonemap.comp
// encodes them to and the thresholds it encodes with, the status block the shader counts
// loop-budget overruns and unfinished pixels in (atomics stay on the device); and host-visible
// copies to read the sums or bytes back, and the status: one copy per submission in flight, so
// that the host reads the counters of the submission it waited for, not the newer one's. The host
// fills the camera block and the thresholds with vkCmdUpdateBuffer, inside the command stream.
struct render_targets {
  // `pixels`: the largest band's pixels over all its views.
  render_targets(const gpu_context& ctx, VkDeviceSize pixels);

  // The buffers a render allocates, the scene's in between, in the order check_device_fits
  // reports them.
  static std::vector<buffer_request> buffers(const std::vector<buffer_request>& scene_buffers,
                                             VkDeviceSize pixels);

  VkDeviceSize pixels;  // what the buffers hold

 private:
  buffer_set device_;  // sums, bytes, cameras, thresholds, status
  buffer_set host_;    // readback, then a status readback per slot

 public:
  gpu_buffer& cameras;     // camera_ubo per view of the group (uniform)
  gpu_buffer& sums;        // pixel_sum per pixel (storage)
  gpu_buffer& bytes;       // RGBA8 per pixel (storage)
  gpu_buffer& thresholds;  // byte_thresholds as uvec2[256] (storage)
  gpu_buffer& status;      // render_status (storage)
  gpu_buffer& readback;    // sums or bytes, copied back
  // render_status, copied back after every submission into its slot's (< submission_slots).
  gpu_buffer& status_readback(std::uint32_t slot) { return host_[1 + slot]; }
};

}  // namespace rtvk::gpu
