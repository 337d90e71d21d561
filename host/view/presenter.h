#pragma once
#include <cstdint>
#include <memory>

#include "buffer.h"
#include "context.h"
#include "swapchain.h"
#include "vk_handle.h"

namespace rtvk::view {

// Shows 8-bit images in the window: the host writes RGBA8 pixels (red in the low byte) into a
// mapped upload buffer, a copy puts them in an image of the render's size, and a blit scales
// that into the swapchain image, centred with its aspect kept and the rest black.
class presenter {
 public:
  presenter(gpu::gpu_context& ctx, int width, int height);
  ~presenter();
  presenter(const presenter&) = delete;
  presenter& operator=(const presenter&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  // Where the next frame's width * height RGBA8 pixels go.
  void write(const std::uint32_t* rgba);

  // Records the copy and the blit into swapchain image `target` of `chain`; the image ends
  // ready to present.
  void record(VkCommandBuffer cb, const swapchain& chain, std::uint32_t target) const;

 private:
  gpu::gpu_context& ctx_;
  int width_, height_;                        // the render's pixels
  std::unique_ptr<gpu::gpu_buffer> staging_;  // mapped: the host writes pixels here
  gpu::unique_memory memory_;                 // the image's
  gpu::unique_image image_;                   // the render's size, R8G8B8A8_UNORM
};

}  // namespace rtvk::view
