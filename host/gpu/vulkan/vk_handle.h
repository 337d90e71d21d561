#pragma once
#include <volk.h>

#include <utility>

namespace rtvk::gpu {

// Owns one Vulkan handle and destroys it with destroy(owner, handle, nullptr) -- the shape of
// every vkDestroy* for objects that belong to a device or an instance. `destroy` names volk's
// function pointer, read when the handle dies, so it is always the loaded entry point.
template <typename Owner, typename Handle, auto& destroy>
class owned_handle {
 public:
  owned_handle() = default;
  owned_handle(Owner owner, Handle handle) : owner_(owner), handle_(handle) {}
  ~owned_handle() { reset(); }
  owned_handle(owned_handle&& o) noexcept
      : owner_(o.owner_), handle_(std::exchange(o.handle_, Handle(VK_NULL_HANDLE))) {}
  owned_handle& operator=(owned_handle&& o) noexcept {
    if (this != &o) {
      reset();
      owner_ = o.owner_;
      handle_ = std::exchange(o.handle_, Handle(VK_NULL_HANDLE));
    }
    return *this;
  }

  Handle get() const { return handle_; }
  void reset() {
    if (handle_ != VK_NULL_HANDLE) destroy(owner_, handle_, nullptr);
    handle_ = VK_NULL_HANDLE;
  }
  // Gives the handle up without destroying it (after a device hang, destroying may block).
  void release() { handle_ = VK_NULL_HANDLE; }

 private:
  Owner owner_ = VK_NULL_HANDLE;    // the device or instance the handle belongs to
  Handle handle_ = VK_NULL_HANDLE;  // the owned object
};

// Owns a top-level handle destroyed with destroy(handle, nullptr): VkInstance, VkDevice.
template <typename Handle, auto& destroy>
class root_handle {
 public:
  root_handle() = default;
  explicit root_handle(Handle handle) : handle_(handle) {}
  ~root_handle() { reset(); }
  root_handle(root_handle&& o) noexcept
      : handle_(std::exchange(o.handle_, Handle(VK_NULL_HANDLE))) {}
  root_handle& operator=(root_handle&& o) noexcept {
    if (this != &o) {
      reset();
      handle_ = std::exchange(o.handle_, Handle(VK_NULL_HANDLE));
    }
    return *this;
  }

  Handle get() const { return handle_; }
  void reset() {
    if (handle_ != VK_NULL_HANDLE) destroy(handle_, nullptr);
    handle_ = VK_NULL_HANDLE;
  }
  void release() { handle_ = VK_NULL_HANDLE; }

 private:
  Handle handle_ = VK_NULL_HANDLE;  // the owned object
};

template <typename Handle, auto& destroy>
using device_handle = owned_handle<VkDevice, Handle, destroy>;

using unique_buffer = device_handle<VkBuffer, vkDestroyBuffer>;
using unique_memory = device_handle<VkDeviceMemory, vkFreeMemory>;
using unique_shader_module = device_handle<VkShaderModule, vkDestroyShaderModule>;
using unique_set_layout = device_handle<VkDescriptorSetLayout, vkDestroyDescriptorSetLayout>;
using unique_pipeline_layout = device_handle<VkPipelineLayout, vkDestroyPipelineLayout>;
using unique_pipeline = device_handle<VkPipeline, vkDestroyPipeline>;
using unique_descriptor_pool = device_handle<VkDescriptorPool, vkDestroyDescriptorPool>;
using unique_command_pool = device_handle<VkCommandPool, vkDestroyCommandPool>;
using unique_fence = device_handle<VkFence, vkDestroyFence>;
using unique_query_pool = device_handle<VkQueryPool, vkDestroyQueryPool>;
using unique_pipeline_cache = device_handle<VkPipelineCache, vkDestroyPipelineCache>;
using unique_messenger =
    owned_handle<VkInstance, VkDebugUtilsMessengerEXT, vkDestroyDebugUtilsMessengerEXT>;
using unique_surface = owned_handle<VkInstance, VkSurfaceKHR, vkDestroySurfaceKHR>;
using unique_swapchain = device_handle<VkSwapchainKHR, vkDestroySwapchainKHR>;
using unique_semaphore = device_handle<VkSemaphore, vkDestroySemaphore>;
using unique_image = device_handle<VkImage, vkDestroyImage>;
using unique_acceleration_structure =
    device_handle<VkAccelerationStructureKHR, vkDestroyAccelerationStructureKHR>;
using unique_instance = root_handle<VkInstance, vkDestroyInstance>;
using unique_device = root_handle<VkDevice, vkDestroyDevice>;

}  // namespace rtvk::gpu
