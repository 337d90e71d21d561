#include "context.h"

#include <cstring>

#include "format.h"
#include "pin_drivers.h"
#include "vk_error.h"

namespace rtvk::gpu {
namespace {

// A command buffer freed back to its pool when it goes out of scope.
class scoped_command_buffer {
 public:
  scoped_command_buffer(VkDevice device, VkCommandPool pool) : device_(device), pool_(pool) {
    VkCommandBufferAllocateInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    info.commandPool = pool;
    info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    info.commandBufferCount = 1;
    vk_check(vkAllocateCommandBuffers(device, &info, &cb_), "vkAllocateCommandBuffers");
  }
  ~scoped_command_buffer() {
    if (cb_) vkFreeCommandBuffers(device_, pool_, 1, &cb_);
  }
  scoped_command_buffer(const scoped_command_buffer&) = delete;
  scoped_command_buffer& operator=(const scoped_command_buffer&) = delete;
  VkCommandBuffer get() const { return cb_; }
  void release() { cb_ = VK_NULL_HANDLE; }

 private:
  VkDevice device_;
  VkCommandPool pool_;
  VkCommandBuffer cb_ = VK_NULL_HANDLE;
};

template <typename T>
void cap(T& value, T most) {
  if (most != 0 && (value == 0 || most < value)) value = most;
}

void apply_caps(const device_limit_caps& caps, device_info& d,
                VkPhysicalDeviceMemoryProperties& memory) {
  cap<VkDeviceSize>(d.max_allocation_size, caps.allocation_size);
  cap<std::uint32_t>(d.limits.maxStorageBufferRange, std::uint32_t(caps.storage_range));
  cap<std::uint32_t>(d.limits.maxMemoryAllocationCount, caps.allocations);
  for (std::uint32_t h = 0; h < memory.memoryHeapCount; ++h)
    cap<VkDeviceSize>(memory.memoryHeaps[h].size, caps.heap_size);
}

}  // namespace

gpu_context::gpu_context(const gpu_options& options)
    : options_(options), instance_(options.validate) {
  devices_ = list_devices(instance_.get());
  chosen_ = select_device(devices_, options.device);
  const device_info& d = devices_[chosen_];
  vkGetPhysicalDeviceMemoryProperties(d.handle, &memory_);
  apply_caps(options.caps, devices_[chosen_], memory_);

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue_info{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue_info.queueFamilyIndex = d.compute_queue_family;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;
  std::vector<const char*> extensions;
  // A portability implementation must have its subset extension enabled.
  if (has_device_extension(d.handle, "VK_KHR_portability_subset"))
    extensions.push_back("VK_KHR_portability_subset");
  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue_info;
  info.enabledExtensionCount = std::uint32_t(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  VkDevice device = VK_NULL_HANDLE;
  vk_check(vkCreateDevice(d.handle, &info, nullptr, &device), "vkCreateDevice");
  device_ = unique_device(device);
  volkLoadDevice(device);
  pin_driver_libraries();
  vkGetDeviceQueue(device, d.compute_queue_family, 0, &queue_);

  VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool_info.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
  pool_info.queueFamilyIndex = d.compute_queue_family;
  VkCommandPool pool = VK_NULL_HANDLE;
  vk_check(vkCreateCommandPool(device, &pool_info, nullptr, &pool), "vkCreateCommandPool");
  pool_ = unique_command_pool(device, pool);

  VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VkFence fence = VK_NULL_HANDLE;
  vk_check(vkCreateFence(device, &fence_info, nullptr, &fence), "vkCreateFence");
  fence_ = unique_fence(device, fence);
}

gpu_context::~gpu_context() {
  if (lost_) {
    // Work may still be pending on a hung device: destroying it could block or crash, and the
    // process is about to report the failure anyway. Leak rather than hang.
    fence_.release();
    pool_.release();
    device_.release();
    instance_.abandon();
    return;
  }
  if (device_.get()) vkDeviceWaitIdle(device_.get());
}

std::uint32_t gpu_context::memory_type(std::uint32_t type_bits, VkMemoryPropertyFlags required,
                                       VkMemoryPropertyFlags preferred) const {
  for (const VkMemoryPropertyFlags want : {required | preferred, required}) {
    for (std::uint32_t i = 0; i < memory_.memoryTypeCount; ++i) {
      if ((type_bits & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & want) == want)
        return i;
    }
  }
  throw std::runtime_error("no memory type with property flags " + std::to_string(required) +
                           " on " + device().name);
}

bool gpu_context::memory_type_has(std::uint32_t type, VkMemoryPropertyFlags flags) const {
  return (memory_.memoryTypes[type].propertyFlags & flags) == flags;
}

void gpu_context::submit_and_wait(const std::function<void(VkCommandBuffer)>& record) {
  if (lost_) throw std::runtime_error("the Vulkan device " + device().name + " is unusable");
  scoped_command_buffer cb(device_.get(), pool_.get());
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vk_check(vkBeginCommandBuffer(cb.get(), &begin), "vkBeginCommandBuffer");
  record(cb.get());
  vk_check(vkEndCommandBuffer(cb.get()), "vkEndCommandBuffer");

  const VkFence fence = fence_.get();
  vk_check(vkResetFences(device_.get(), 1, &fence), "vkResetFences");
  VkCommandBuffer handle = cb.get();
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &handle;
  VkResult r = vkQueueSubmit(queue_, 1, &submit, fence);
  if (r == VK_SUCCESS) {
    const auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(options_.fence_timeout);
    r = vkWaitForFences(device_.get(), 1, &fence, VK_TRUE, std::uint64_t(ns.count()));
    if (r == VK_SUCCESS) return;
    lost_ = true;
    cb.release();  // still pending: it must not be freed
    throw vk_error(
        "vkWaitForFences", r,
        "device " + device().name +
            (r == VK_TIMEOUT ? ", no answer after " + format_number(double(ns.count()) / 1e9) + " s"
                             : ""));
  }
  if (r == VK_ERROR_DEVICE_LOST) lost_ = true;
  throw vk_error("vkQueueSubmit", r, "device " + device().name);
}

}  // namespace rtvk::gpu
