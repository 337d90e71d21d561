#pragma once
#include <cstdint>
#include <vector>

#include "context.h"
#include "vk_handle.h"

namespace rtvk::view {

// The window surface's images, recreated when the window's size changes. Images are written by
// transfers (a copy and a blit), so the surface must allow TRANSFER_DST; presentation is FIFO
// (every Vulkan surface has it). Owned by the caller; the context and its surface outlive it.
class swapchain {
 public:
  swapchain(gpu::gpu_context& ctx, int width, int height);
  ~swapchain();
  swapchain(const swapchain&) = delete;
  swapchain& operator=(const swapchain&) = delete;

  // Makes new images for this size, after the device has finished with the old ones.
  void recreate(int width, int height);

  VkExtent2D extent() const { return extent_; }
  VkFormat format() const { return format_; }
  VkImage image(std::uint32_t index) const { return images_[index]; }
  // Signalled when presenting image `index` may begin (one per image: a present waits on it).
  VkSemaphore ready_to_present(std::uint32_t index) const { return present_ready_[index].get(); }

  // The next image to draw, once `acquired` is signalled; false when the swapchain no longer
  // matches the surface (recreate it).
  bool acquire(VkSemaphore acquired, std::uint32_t& index);
  // Queues image `index` for presentation; false when the swapchain no longer matches.
  bool present(std::uint32_t index);

 private:
  void create(int width, int height);

  gpu::gpu_context& ctx_;
  VkFormat format_ = VK_FORMAT_UNDEFINED;             // of the images
  VkExtent2D extent_{};                               // pixels
  gpu::unique_swapchain swapchain_;                   // the images' owner
  std::vector<VkImage> images_;                       // owned by swapchain_
  std::vector<gpu::unique_semaphore> present_ready_;  // per image
};

}  // namespace rtvk::view
