#pragma once
#include <cstdint>
#include <memory>

#include "buffer.h"
#include "compute_pipeline.h"
#include "context.h"
#include "overlay.h"
#include "swapchain.h"
#include "vk_handle.h"

namespace rtvk::view {

// Shows the engine's accumulated image in the window without it leaving the device: a copy puts
// the RGBA8 bytes (gpu_engine::accumulated_bytes) in an image of the render's size, overlay.comp
// composes the overlay's band from those bytes and the text's mask (the only thing the host
// sends, a few KiB, in the command stream) and a copy lays it over the image's top left, and a
// blit scales the image into the swapchain image, centred with its aspect kept and the rest
// black.
class presenter {
 public:
  presenter(gpu::gpu_context& ctx, int width, int height);
  ~presenter();
  presenter(const presenter&) = delete;
  presenter& operator=(const presenter&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }

  // Frames show `bytes` (width x height RGBA8, written by earlier commands of the queue) from
  // now on; before recording, outside any submission (a new buffer waits for the frames in
  // flight).
  void show_from(VkBuffer bytes);
  // Records the frame into swapchain image `target` of `chain`: the bytes with `overlay` over
  // them when it has a band; the swapchain image ends ready to present.
  void record(VkCommandBuffer cb, const overlay_mask& overlay, const swapchain& chain,
              std::uint32_t target) const;

 private:
  void record_overlay(VkCommandBuffer cb, const overlay_mask& overlay) const;

  gpu::gpu_context& ctx_;
  int width_, height_;               // the render's pixels
  gpu::buffer_set overlay_buffers_;  // the mask (as the host draws it), the band (composed)
  std::unique_ptr<gpu::compute_pipeline> compose_;  // overlay.comp, bound to the last `bytes`
  VkBuffer bound_bytes_ = VK_NULL_HANDLE;           // what compose_ reads
  gpu::unique_memory memory_;                       // the image's
  gpu::unique_image image_;                         // the render's size, R8G8B8A8_UNORM
};

}  // namespace rtvk::view
