#include "context.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>

#include "format.h"
#include "pin_drivers.h"
#include "vk_error.h"

namespace rtvk::gpu {
namespace {

template <typename T>
void cap(T& value, T most) {
  if (most != 0 && (value == 0 || most < value)) value = most;
}

void apply_caps(const device_limit_caps& caps, device_info& d,
                VkPhysicalDeviceMemoryProperties& memory) {
  cap<VkDeviceSize>(d.max_allocation_size, caps.allocation_size);
  cap<std::uint32_t>(d.limits.maxStorageBufferRange, std::uint32_t(caps.storage_range));
  cap<std::uint32_t>(d.limits.maxMemoryAllocationCount, caps.allocations);
  cap<std::uint32_t>(d.limits.maxComputeWorkGroupCount[0], caps.workgroup_count);
  for (std::uint32_t h = 0; h < memory.memoryHeapCount; ++h)
    cap<VkDeviceSize>(memory.memoryHeaps[h].size, caps.heap_size);
}

// The family a window's frames go through: the viewer composes its overlay (a dispatch), blits
// (a graphics command) and presents there, so it needs a family with compute and graphics that
// presents to the surface. Renders stay on the compute family.
std::uint32_t presenting_family(const device_info& d, VkSurfaceKHR surface) {
  if (!has_device_extension(d.handle, VK_KHR_SWAPCHAIN_EXTENSION_NAME))
    throw std::runtime_error("the Vulkan device " + d.name + " cannot present to the window (no " +
                             VK_KHR_SWAPCHAIN_EXTENSION_NAME + ")");
  const VkQueueFlags needs = VK_QUEUE_COMPUTE_BIT | VK_QUEUE_GRAPHICS_BIT;
  bool any_presents = false;
  for (std::uint32_t k = 0; k < d.queue_families.size(); ++k) {
    if (d.queue_families[k].queueCount == 0) continue;
    VkBool32 presents = VK_FALSE;
    vk_check(vkGetPhysicalDeviceSurfaceSupportKHR(d.handle, k, surface, &presents),
             "vkGetPhysicalDeviceSurfaceSupportKHR");
    any_presents = any_presents || presents;
    if (presents && (d.queue_families[k].queueFlags & needs) == needs) return k;
  }
  throw std::runtime_error(
      "the Vulkan device " + d.name +
      (any_presents ? " presents to the window only from queues that cannot also compute and draw"
                    : " cannot present to the window from any of its queues"));
}

// The features hardware ray tracing needs, chained for vkCreateDevice: device addresses,
// acceleration structures, and ray queries and pipelines where the device has them.
struct ray_tracing_features {
  VkPhysicalDeviceBufferDeviceAddressFeatures address{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_BUFFER_DEVICE_ADDRESS_FEATURES};
  VkPhysicalDeviceAccelerationStructureFeaturesKHR structures{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
  VkPhysicalDeviceRayQueryFeaturesKHR query{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR};
  VkPhysicalDeviceRayTracingPipelineFeaturesKHR pipeline{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR};
  void chain(bool queries, bool pipelines) {
    address.bufferDeviceAddress = VK_TRUE;
    structures.accelerationStructure = VK_TRUE;
    address.pNext = &structures;
    void** next = &structures.pNext;
    if (queries) {
      query.rayQuery = VK_TRUE;
      *next = &query;
      next = &query.pNext;
    }
    if (pipelines) {
      pipeline.rayTracingPipeline = VK_TRUE;
      *next = &pipeline;
    }
  }
};

}  // namespace

gpu_context::gpu_context(const gpu_options& options)
    : options_(options), instance_(options.validate, options.instance_extensions) {
  devices_ = list_devices(instance_.get());
  chosen_ = select_device(devices_, options.device, options.device_source);
  const device_info& d = devices_[chosen_];
  std::uint32_t presenting = d.compute_queue_family;
  if (options.make_surface) {
    surface_ = unique_surface(instance_.get(), options.make_surface(instance_.get()));
    presenting = presenting_family(d, surface_.get());
  }
  vkGetPhysicalDeviceMemoryProperties(d.handle, &memory_);
  apply_caps(options.caps, devices_[chosen_], memory_);

  const float priority = 1.0f;
  std::vector<VkDeviceQueueCreateInfo> queue_infos;
  for (const std::uint32_t family : {d.compute_queue_family, presenting}) {
    if (!queue_infos.empty() && queue_infos[0].queueFamilyIndex == family) break;
    VkDeviceQueueCreateInfo queue_info{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queue_info.queueFamilyIndex = family;
    queue_info.queueCount = 1;
    queue_info.pQueuePriorities = &priority;
    queue_infos.push_back(queue_info);
  }
  std::vector<const char*> extensions;
  // A portability implementation must have its subset extension enabled.
  if (has_device_extension(d.handle, "VK_KHR_portability_subset"))
    extensions.push_back("VK_KHR_portability_subset");
  if (surface_.get()) extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
  ray_tracing_features rt;
  if (options.ray_tracing && d.acceleration_structures) {
    for (const char* e : ray_tracing_extensions(d)) extensions.push_back(e);
    ray_queries_ = d.ray_queries;
    ray_tracing_pipelines_ = d.ray_tracing_pipelines;
    rt.chain(ray_queries_, ray_tracing_pipelines_);
  }
  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  if (options.ray_tracing && d.acceleration_structures) info.pNext = &rt.address;
  info.queueCreateInfoCount = std::uint32_t(queue_infos.size());
  info.pQueueCreateInfos = queue_infos.data();
  info.enabledExtensionCount = std::uint32_t(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  VkDevice device = VK_NULL_HANDLE;
  vk_check(vkCreateDevice(d.handle, &info, nullptr, &device), "vkCreateDevice");
  device_ = unique_device(device);
  volkLoadDevice(device);
  pin_driver_libraries();
  open_lane(compute_, d.compute_queue_family);
  if (presenting != d.compute_queue_family) {
    presenting_ = std::make_unique<queue_lane>();
    open_lane(*presenting_, presenting);
  }
}

void gpu_context::open_lane(queue_lane& l, std::uint32_t family) {
  const VkDevice device = device_.get();
  l.family = family;
  vkGetDeviceQueue(device, family, 0, &l.queue);
  VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool_info.flags =
      VK_COMMAND_POOL_CREATE_TRANSIENT_BIT | VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool_info.queueFamilyIndex = family;
  VkCommandPool pool = VK_NULL_HANDLE;
  vk_check(vkCreateCommandPool(device, &pool_info, nullptr, &pool), "vkCreateCommandPool");
  l.pool = unique_command_pool(device, pool);
  for (slot& s : l.slots) {
    VkCommandBufferAllocateInfo cb_info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    cb_info.commandPool = pool;
    cb_info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    cb_info.commandBufferCount = 1;
    vk_check(vkAllocateCommandBuffers(device, &cb_info, &s.cb), "vkAllocateCommandBuffers");
    VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence = VK_NULL_HANDLE;
    vk_check(vkCreateFence(device, &fence_info, nullptr, &fence), "vkCreateFence");
    s.fence = unique_fence(device, fence);
  }
}

void gpu_context::abandon(queue_lane& l) noexcept {
  for (slot& s : l.slots) s.fence.release();
  l.pool.release();
}

gpu_context::~gpu_context() {
  if (lost_) {
    // Work may still be pending on a hung device: destroying it could block or crash, and the
    // process is about to report the failure anyway. Leak rather than hang.
    abandon(compute_);
    if (presenting_) abandon(*presenting_);
    device_.release();
    surface_.release();
    instance_.abandon();
    return;
  }
  if (device_.get()) vkDeviceWaitIdle(device_.get());
}

std::vector<std::uint32_t> gpu_context::shared_families() const {
  if (!presenting_) return {};
  return {compute_.family, presenting_->family};
}

std::uint32_t gpu_context::memory_type(std::uint32_t type_bits, VkMemoryPropertyFlags required,
                                       VkMemoryPropertyFlags preferred,
                                       VkMemoryPropertyFlags avoided) const {
  // Never chosen while another type fits: memory the host cannot read back normally, or that
  // may not exist until used.
  const VkMemoryPropertyFlags odd =
      VK_MEMORY_PROPERTY_PROTECTED_BIT | VK_MEMORY_PROPERTY_LAZILY_ALLOCATED_BIT |
      VK_MEMORY_PROPERTY_DEVICE_COHERENT_BIT_AMD | VK_MEMORY_PROPERTY_DEVICE_UNCACHED_BIT_AMD;
  // Ranked by: no odd property, the preferred ones present, the avoided ones absent, the
  // driver's order (drivers list their best type of a kind first).
  const auto rank = [&](VkMemoryPropertyFlags f) {
    return std::array<int, 3>{(f & odd & ~required) == 0,
                              std::popcount(std::uint32_t(f & preferred)),
                              -std::popcount(std::uint32_t(f & avoided))};
  };
  std::uint32_t best = ~0u;
  for (std::uint32_t i = 0; i < memory_.memoryTypeCount; ++i) {
    const VkMemoryPropertyFlags f = memory_.memoryTypes[i].propertyFlags;
    if (!(type_bits & (1u << i)) || (f & required) != required) continue;
    if (best == ~0u || rank(f) > rank(memory_.memoryTypes[best].propertyFlags)) best = i;
  }
  if (best != ~0u) return best;
  throw std::runtime_error("no memory type with property flags " + std::to_string(required) +
                           " on " + device().name);
}

std::vector<gpu_context::heap_room> gpu_context::heap_rooms() const {
  std::vector<heap_room> out;
  for (std::uint32_t h = 0; h < memory_.memoryHeapCount; ++h)
    out.push_back({memory_.memoryHeaps[h].size, false});  // already capped by apply_caps
  if (!has_device_extension(device().handle, VK_EXT_MEMORY_BUDGET_EXTENSION_NAME)) return out;
  VkPhysicalDeviceMemoryBudgetPropertiesEXT budget{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MEMORY_BUDGET_PROPERTIES_EXT};
  VkPhysicalDeviceMemoryProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MEMORY_PROPERTIES_2};
  props.pNext = &budget;
  vkGetPhysicalDeviceMemoryProperties2(device().handle, &props);
  for (std::uint32_t h = 0; h < memory_.memoryHeapCount && h < VK_MAX_MEMORY_HEAPS; ++h) {
    // A driver may report a budget below what is in use (another process grew): no room.
    VkDeviceSize room =
        budget.heapBudget[h] > budget.heapUsage[h] ? budget.heapBudget[h] - budget.heapUsage[h] : 0;
    if (budget.heapBudget[h] == 0) continue;  // no figure for this heap
    if (room < out[h].bytes) out[h] = {room, true};
  }
  return out;
}

bool gpu_context::memory_type_has(std::uint32_t type, VkMemoryPropertyFlags flags) const {
  return (memory_.memoryTypes[type].propertyFlags & flags) == flags;
}

void gpu_context::submit_and_wait(const std::function<void(VkCommandBuffer)>& record) {
  wait(submit(record));
}

std::uint64_t gpu_context::submit(const std::function<void(VkCommandBuffer)>& record,
                                  const submit_sync& sync, queue_role role) {
  if (lost_) throw std::runtime_error("the Vulkan device " + device().name + " is unusable");
  queue_lane& l = lane(role);
  const std::uint64_t ticket = l.submitted + 1;
  slot& s = l.slots[ticket % submission_slots];
  if (s.ticket != 0) wait(s.ticket, role);  // its command buffer and fence are about to be reused
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vk_check(vkBeginCommandBuffer(s.cb, &begin), "vkBeginCommandBuffer");
  first_run_recorded_ = false;
  try {
    record(s.cb);
    vk_check(vkEndCommandBuffer(s.cb), "vkEndCommandBuffer");
  } catch (...) {  // back to the initial state, so the slot can be recorded again
    vkResetCommandBuffer(s.cb, 0);
    first_run_recorded_ = false;
    throw;
  }
  s.first_run = first_run_recorded_;
  first_run_recorded_ = false;

  const VkFence fence = s.fence.get();
  vk_check(vkResetFences(device_.get(), 1, &fence), "vkResetFences");
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &s.cb;
  if (sync.wait) {
    submit.waitSemaphoreCount = 1;
    submit.pWaitSemaphores = &sync.wait;
    submit.pWaitDstStageMask = &sync.wait_stage;
  }
  if (sync.signal) {
    submit.signalSemaphoreCount = 1;
    submit.pSignalSemaphores = &sync.signal;
  }
  const VkResult r = vkQueueSubmit(l.queue, 1, &submit, fence);
  if (r != VK_SUCCESS) {
    if (r == VK_ERROR_DEVICE_LOST) lost_ = true;
    throw vk_error("vkQueueSubmit", r, "device " + device().name);
  }
  l.submitted = s.ticket = ticket;
  return ticket;
}

void gpu_context::wait(std::uint64_t ticket, queue_role role) {
  queue_lane& l = lane(role);
  if (ticket <= l.completed) return;
  if (lost_) throw std::runtime_error("the Vulkan device " + device().name + " is unusable");
  // Submissions on one queue complete in order, so waiting for the oldest first loses nothing.
  for (std::uint64_t t = l.completed + 1; t <= ticket; ++t) {
    slot& s = l.slots[t % submission_slots];
    if (s.ticket != t) continue;  // never submitted (a failed submit) or already reused
    const VkFence fence = s.fence.get();
    const bool compiling = s.first_run && compiles_in_first_run(device());
    const auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(
        options_.fence_timeout + (compiling ? std::chrono::milliseconds(first_run_allowance)
                                            : std::chrono::milliseconds(0)));
    const VkResult r =
        vkWaitForFences(device_.get(), 1, &fence, VK_TRUE, std::uint64_t(ns.count()));
    if (r != VK_SUCCESS) {
      lost_ = true;  // its command buffer is still pending: the pool is leaked, not destroyed
      std::string why = "device " + device().name;
      if (r == VK_TIMEOUT)
        why += ", no answer after " + format_number(double(ns.count()) / 1e9) + " s";
      if (r == VK_TIMEOUT && compiling)
        why +=
            " (--gpu-timeout and the allowance for lavapipe's compile of a pipeline's shaders "
            "in its first run)";
      throw vk_error("vkWaitForFences", r, why);
    }
    l.completed = t;
  }
  l.completed = std::max(l.completed, ticket);
}

void gpu_context::check_validation(const std::string& consequence) const {
  if (validation_messages() > 0)
    throw std::runtime_error("the Vulkan validation layer reported " +
                             std::to_string(validation_messages()) + " problem(s) (above)" +
                             consequence);
}

void gpu_context::wait_all(queue_lane& l) noexcept {
  if (lost_ || l.submitted == l.completed) return;
  try {
    wait(l.submitted, &l == &compute_ ? queue_role::compute : queue_role::presenting);
  } catch (...) {  // lost_ is set: the owners give their handles up
  }
}

void gpu_context::wait_all() noexcept {
  wait_all(compute_);
  if (presenting_) wait_all(*presenting_);
}

}  // namespace rtvk::gpu
