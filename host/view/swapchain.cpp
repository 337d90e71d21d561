#include "swapchain.h"

#include <algorithm>
#include <stdexcept>

#include "vk_error.h"

namespace rtvk::view {
namespace {

// A UNORM format: the bytes rtvk writes are already gamma encoded as the scene asks (an sRGB
// format would encode them again).
VkSurfaceFormatKHR pick_format(VkPhysicalDevice device, VkSurfaceKHR surface) {
  std::uint32_t n = 0;
  gpu::vk_check(vkGetPhysicalDeviceSurfaceFormatsKHR(device, surface, &n, nullptr),
                "vkGetPhysicalDeviceSurfaceFormatsKHR");
  std::vector<VkSurfaceFormatKHR> formats(n);
  gpu::vk_check(vkGetPhysicalDeviceSurfaceFormatsKHR(device, surface, &n, formats.data()),
                "vkGetPhysicalDeviceSurfaceFormatsKHR");
  for (const VkSurfaceFormatKHR& f : formats)
    if (f.format == VK_FORMAT_B8G8R8A8_UNORM || f.format == VK_FORMAT_R8G8B8A8_UNORM) return f;
  if (formats.empty()) throw std::runtime_error("the window's surface offers no image format");
  return formats.front();
}

}  // namespace

swapchain::swapchain(gpu::gpu_context& ctx, int width, int height) : ctx_(ctx) {
  create(width, height);
}

swapchain::~swapchain() {
  ctx_.wait_all();
}

void swapchain::recreate(int width, int height) {
  ctx_.wait_all();
  vkDeviceWaitIdle(ctx_.vk());  // presentation may still read the old images
  create(width, height);
}

void swapchain::create(int width, int height) {
  const VkPhysicalDevice device = ctx_.device().handle;
  const VkSurfaceKHR surface = ctx_.surface();
  VkSurfaceCapabilitiesKHR caps{};
  gpu::vk_check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(device, surface, &caps),
                "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
  if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT))
    throw std::runtime_error("the window's surface on " + ctx_.device().name +
                             " cannot be written by transfers (no TRANSFER_DST usage)");
  const VkSurfaceFormatKHR format = pick_format(device, surface);
  if (caps.currentExtent.width != 0xFFFFFFFFu) {
    extent_ = caps.currentExtent;
  } else {
    extent_.width =
        std::clamp(std::uint32_t(width), caps.minImageExtent.width, caps.maxImageExtent.width);
    extent_.height =
        std::clamp(std::uint32_t(height), caps.minImageExtent.height, caps.maxImageExtent.height);
  }
  std::uint32_t count = caps.minImageCount + 1;
  if (caps.maxImageCount > 0) count = std::min(count, caps.maxImageCount);

  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = surface;
  info.minImageCount = count;
  info.imageFormat = format.format;
  info.imageColorSpace = format.colorSpace;
  info.imageExtent = extent_;
  info.imageArrayLayers = 1;
  info.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = caps.currentTransform;
  info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
  if (!(caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR))
    info.compositeAlpha =
        VkCompositeAlphaFlagBitsKHR(caps.supportedCompositeAlpha & -caps.supportedCompositeAlpha);
  info.presentMode = VK_PRESENT_MODE_FIFO_KHR;
  info.clipped = VK_TRUE;
  info.oldSwapchain = swapchain_.get();
  VkSwapchainKHR made = VK_NULL_HANDLE;
  gpu::vk_check(vkCreateSwapchainKHR(ctx_.vk(), &info, nullptr, &made), "vkCreateSwapchainKHR");
  swapchain_ = gpu::unique_swapchain(ctx_.vk(), made);
  format_ = format.format;

  gpu::vk_check(vkGetSwapchainImagesKHR(ctx_.vk(), made, &count, nullptr),
                "vkGetSwapchainImagesKHR");
  images_.resize(count);
  gpu::vk_check(vkGetSwapchainImagesKHR(ctx_.vk(), made, &count, images_.data()),
                "vkGetSwapchainImagesKHR");
  present_ready_.clear();
  for (std::uint32_t i = 0; i < count; ++i) {
    VkSemaphoreCreateInfo s{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore sem = VK_NULL_HANDLE;
    gpu::vk_check(vkCreateSemaphore(ctx_.vk(), &s, nullptr, &sem), "vkCreateSemaphore");
    present_ready_.emplace_back(ctx_.vk(), sem);
  }
}

bool swapchain::acquire(VkSemaphore acquired, std::uint32_t& index) {
  const VkResult r = vkAcquireNextImageKHR(ctx_.vk(), swapchain_.get(), UINT64_MAX, acquired,
                                           VK_NULL_HANDLE, &index);
  if (r == VK_ERROR_OUT_OF_DATE_KHR) return false;
  if (r != VK_SUCCESS && r != VK_SUBOPTIMAL_KHR) throw gpu::vk_error("vkAcquireNextImageKHR", r);
  return true;
}

bool swapchain::present(std::uint32_t index) {
  const VkSemaphore wait = present_ready_[index].get();
  const VkSwapchainKHR chain = swapchain_.get();
  VkPresentInfoKHR info{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  info.waitSemaphoreCount = 1;
  info.pWaitSemaphores = &wait;
  info.swapchainCount = 1;
  info.pSwapchains = &chain;
  info.pImageIndices = &index;
  const VkResult r = vkQueuePresentKHR(ctx_.queue(gpu::queue_role::presenting), &info);
  if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR) return false;
  if (r != VK_SUCCESS) throw gpu::vk_error("vkQueuePresentKHR", r);
  return true;
}

}  // namespace rtvk::view
