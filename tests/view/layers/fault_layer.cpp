// A Vulkan layer for tests (tests/fault_layer.h loads it) that makes a device fail the way real
// ones do, chosen by the environment variable RTVK_TEST_FAULT; everything else passes through:
//   no-present                   no queue can present to any surface
//                                (vkGetPhysicalDeviceSurfaceSupportKHR says VK_FALSE)
//   lose-device-at-submit:N      the Nth vkQueueSubmit and every later one: VK_ERROR_DEVICE_LOST
//   lose-device-after-present:N  every vkQueueSubmit after the Nth present: VK_ERROR_DEVICE_LOST
//   watchdog:MS                  a submission that keeps the queue busy for more than MS
//                                milliseconds loses the device, as Windows' 2-second TDR and
//                                Linux's amdgpu/i915 job timeouts do: that submission and every
//                                later one return VK_ERROR_DEVICE_LOST. Each submission is
//                                waited for before the call returns, so it is timed alone.
//   watchdog-us:US               the same in microseconds (a real GPU runs a small render's
//                                submissions in well under a millisecond)
//   workgroup-count:N            every device says its maxComputeWorkGroupCount is N in x, y and z,
//                                and a dispatch of more workgroups than that in any dimension
//                                loses the device at the next vkQueueSubmit (a real driver's
//                                behaviour past its limits is undefined)
//   no-graphics-queue            every queue family says it cannot do graphics (a compute-only
//                                device, or a driver that presents from its compute queue)
//   vulkan-1.0                   every device says it supports only Vulkan 1.0.0, and a call of
//                                vkGetPhysicalDeviceProperties2 or vkGetPhysicalDeviceFeatures2
//                                for it (functions such a device does not have) aborts the process
//   disguise-device              every device says it is a discrete GPU named "rtvk disguised
//                                GPU" whose driver is NVIDIA's (ID, name and info), so tests
//                                see a loader that offers no software device
//   discrete-memory              every device says its memory is a discrete GPU's without a
//                                host-visible window: type 0 device-local only (heap 0), types
//                                1 and 2 host-visible and coherent, 2 also cached (heap 1); a
//                                vkMapMemory of type 0 fails, and a storage or uniform buffer in
//                                host memory bound for a shader loses the device at the next
//                                vkQueueSubmit (on a real one it crosses PCIe at every access)
//   memory-budget:KIB            every device has VK_EXT_memory_budget and says each heap's
//                                budget is KIB KiB, none of it in use
//   compute-queue-family         every device has one more queue family, last, that computes
//                                and copies but cannot draw or present (AMD's and NVIDIA's
//                                asynchronous compute queues); its queue is the device's family
//                                0 queue underneath, behind a handle of its own. A blit recorded
//                                for it, or a present from it, loses the device at the next
//                                vkQueueSubmit (graphics commands on a compute queue are
//                                undefined); at vkDestroyDevice the layer prints how many
//                                submissions went to compute-only families (its own, and a real
//                                GPU's asynchronous compute families) and to the others ("rtvk
//                                test layer: submissions: C to compute-only families, P to the
//                                others")
// The chain is kept in globals: a test process of rtvk makes one instance and one device.
#include <vulkan/vk_layer.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

namespace {

PFN_vkGetInstanceProcAddr next_instance_proc = nullptr;  // the next layer's, or the loader's
PFN_vkGetDeviceProcAddr next_device_proc = nullptr;
PFN_vkQueueSubmit next_queue_submit = nullptr;
PFN_vkQueuePresentKHR next_queue_present = nullptr;
PFN_vkQueueWaitIdle next_queue_wait_idle = nullptr;
PFN_vkCmdDispatch next_dispatch = nullptr;
PFN_vkCmdDispatchBase next_dispatch_base = nullptr;
// Looked up while the instance is made: later, the loader's answer would be the top of the chain,
// which leads back here.
PFN_vkGetPhysicalDeviceProperties next_properties = nullptr;
PFN_vkGetPhysicalDeviceProperties2 next_properties2 = nullptr;
PFN_vkGetPhysicalDeviceQueueFamilyProperties next_queue_families = nullptr;
PFN_vkGetPhysicalDeviceQueueFamilyProperties2 next_queue_families2 = nullptr;
PFN_vkGetPhysicalDeviceFeatures2 next_features2 = nullptr;
PFN_vkGetPhysicalDeviceMemoryProperties next_memory = nullptr;
PFN_vkGetPhysicalDeviceMemoryProperties2 next_memory2 = nullptr;
PFN_vkEnumerateDeviceExtensionProperties next_device_extensions = nullptr;
PFN_vkGetBufferMemoryRequirements next_buffer_requirements = nullptr;
PFN_vkAllocateMemory next_allocate = nullptr;
PFN_vkMapMemory next_map = nullptr;
PFN_vkBindBufferMemory next_bind_buffer = nullptr;
PFN_vkUpdateDescriptorSets next_update_descriptors = nullptr;
PFN_vkGetDeviceQueue next_get_queue = nullptr;
PFN_vkCreateCommandPool next_create_pool = nullptr;
PFN_vkAllocateCommandBuffers next_allocate_command_buffers = nullptr;
PFN_vkCreateBuffer next_create_buffer = nullptr;
PFN_vkCmdBlitImage next_blit = nullptr;
PFN_vkCmdPipelineBarrier next_pipeline_barrier = nullptr;
PFN_vkDestroyDevice next_destroy_device = nullptr;
VkInstance created_instance = VK_NULL_HANDLE;
std::atomic<long> submits{0}, presents{0};
std::atomic<bool> watchdog_fired{false};
std::atomic<bool> dispatched_past_limit{false};
std::atomic<bool> shader_reads_host_memory{false};
// compute-queue-family: the fake family's index (the device's family count), the handle its
// queue has (a dispatchable object of this layer's: the loader writes its dispatch pointer in the
// first word), the pools and command buffers made for it, submissions counted per queue.
std::uint32_t fake_family = ~0u;  // of the device made (vkCreateDevice sets it)
std::unordered_map<VkPhysicalDevice, std::uint32_t> fake_family_of;  // each device's listing
void* fake_queue_object[2] = {};
VkQueue real_queue_behind_fake = VK_NULL_HANDLE;
std::unordered_map<std::uint64_t, bool> pool_is_fake;
std::unordered_map<VkCommandBuffer, bool> cb_is_fake;
std::vector<VkQueueFamilyProperties> real_families;  // of the device made
std::vector<VkQueue> compute_only_queues;            // its real queues of compute-only families
std::atomic<long> fake_submits{0}, real_submits{0};
std::atomic<bool> graphics_on_compute_queue{false};
// discrete-memory: the type each allocation was made from, and the allocation each buffer is in.
std::mutex memory_mutex;
std::unordered_map<std::uint64_t, std::uint32_t> memory_type_of;
std::unordered_map<std::uint64_t, std::uint64_t> memory_of_buffer;
std::uint32_t real_type_of_fake[3] = {};            // the device's own type behind each fake one
void choose_real_types(VkPhysicalDevice physical);  // sets real_type_of_fake

// The fault's count when RTVK_TEST_FAULT is "name:N", 0 when it is another fault or none.
long fault_count(const char* name) {
  const char* fault = std::getenv("RTVK_TEST_FAULT");
  const std::size_t n = std::strlen(name);
  if (!fault || std::strncmp(fault, name, n) != 0 || fault[n] != ':') return 0;
  return std::strtol(fault + n + 1, nullptr, 10);
}
bool fault_is(const char* name) {
  const char* fault = std::getenv("RTVK_TEST_FAULT");
  return fault && std::strcmp(fault, name) == 0;
}

template <typename Info, typename Link>
Link* find_link(const Info* info, VkStructureType type) {
  auto* p = static_cast<Link*>(const_cast<void*>(info->pNext));
  while (p && !(p->sType == type && p->function == VK_LAYER_LINK_INFO))
    p = static_cast<Link*>(const_cast<void*>(p->pNext));
  return p;
}

VKAPI_ATTR VkResult VKAPI_CALL create_instance(const VkInstanceCreateInfo* info,
                                               const VkAllocationCallbacks* allocator,
                                               VkInstance* instance) {
  auto* link = find_link<VkInstanceCreateInfo, VkLayerInstanceCreateInfo>(
      info, VK_STRUCTURE_TYPE_LOADER_INSTANCE_CREATE_INFO);
  if (!link) return VK_ERROR_INITIALIZATION_FAILED;
  next_instance_proc = link->u.pLayerInfo->pfnNextGetInstanceProcAddr;
  link->u.pLayerInfo = link->u.pLayerInfo->pNext;  // the next layer finds its own link
  auto create = reinterpret_cast<PFN_vkCreateInstance>(
      next_instance_proc(VK_NULL_HANDLE, "vkCreateInstance"));
  const VkResult r = create(info, allocator, instance);
  if (r != VK_SUCCESS) return r;
  created_instance = *instance;
  next_properties = reinterpret_cast<PFN_vkGetPhysicalDeviceProperties>(
      next_instance_proc(*instance, "vkGetPhysicalDeviceProperties"));
  next_properties2 = reinterpret_cast<PFN_vkGetPhysicalDeviceProperties2>(
      next_instance_proc(*instance, "vkGetPhysicalDeviceProperties2"));
  next_queue_families = reinterpret_cast<PFN_vkGetPhysicalDeviceQueueFamilyProperties>(
      next_instance_proc(*instance, "vkGetPhysicalDeviceQueueFamilyProperties"));
  next_queue_families2 = reinterpret_cast<PFN_vkGetPhysicalDeviceQueueFamilyProperties2>(
      next_instance_proc(*instance, "vkGetPhysicalDeviceQueueFamilyProperties2"));
  next_features2 = reinterpret_cast<PFN_vkGetPhysicalDeviceFeatures2>(
      next_instance_proc(*instance, "vkGetPhysicalDeviceFeatures2"));
  next_memory = reinterpret_cast<PFN_vkGetPhysicalDeviceMemoryProperties>(
      next_instance_proc(*instance, "vkGetPhysicalDeviceMemoryProperties"));
  next_memory2 = reinterpret_cast<PFN_vkGetPhysicalDeviceMemoryProperties2>(
      next_instance_proc(*instance, "vkGetPhysicalDeviceMemoryProperties2"));
  next_device_extensions = reinterpret_cast<PFN_vkEnumerateDeviceExtensionProperties>(
      next_instance_proc(*instance, "vkEnumerateDeviceExtensionProperties"));
  return r;
}

VKAPI_ATTR VkResult VKAPI_CALL create_device(VkPhysicalDevice physical,
                                             const VkDeviceCreateInfo* info,
                                             const VkAllocationCallbacks* allocator,
                                             VkDevice* device) {
  auto* link = find_link<VkDeviceCreateInfo, VkLayerDeviceCreateInfo>(
      info, VK_STRUCTURE_TYPE_LOADER_DEVICE_CREATE_INFO);
  if (!link) return VK_ERROR_INITIALIZATION_FAILED;
  const PFN_vkGetInstanceProcAddr next = link->u.pLayerInfo->pfnNextGetInstanceProcAddr;
  next_device_proc = link->u.pLayerInfo->pfnNextGetDeviceProcAddr;
  link->u.pLayerInfo = link->u.pLayerInfo->pNext;
  auto create = reinterpret_cast<PFN_vkCreateDevice>(next(created_instance, "vkCreateDevice"));
  // compute-queue-family: the fake family's queue is family 0's underneath, one queue for both.
  VkDeviceCreateInfo real = *info;
  std::vector<VkDeviceQueueCreateInfo> queues;
  if (fault_is("compute-queue-family")) {
    {
      const std::lock_guard<std::mutex> lock(memory_mutex);
      const auto found = fake_family_of.find(physical);
      fake_family = found == fake_family_of.end() ? ~0u : found->second;
    }
    uint32_t n = 0;
    next_queue_families(physical, &n, nullptr);
    real_families.resize(n);
    next_queue_families(physical, &n, real_families.data());
    for (uint32_t k = 0; k < info->queueCreateInfoCount; ++k) {
      VkDeviceQueueCreateInfo q = info->pQueueCreateInfos[k];
      if (q.queueFamilyIndex == fake_family) q.queueFamilyIndex = 0;
      const bool known = std::any_of(queues.begin(), queues.end(), [&](const auto& e) {
        return e.queueFamilyIndex == q.queueFamilyIndex;
      });
      if (!known) queues.push_back(q);
    }
    real.queueCreateInfoCount = uint32_t(queues.size());
    real.pQueueCreateInfos = queues.data();
  }
  const VkResult r = create(physical, &real, allocator, device);
  if (r != VK_SUCCESS) return r;
  if (fault_is("discrete-memory")) choose_real_types(physical);
  next_queue_submit =
      reinterpret_cast<PFN_vkQueueSubmit>(next_device_proc(*device, "vkQueueSubmit"));
  next_queue_wait_idle =
      reinterpret_cast<PFN_vkQueueWaitIdle>(next_device_proc(*device, "vkQueueWaitIdle"));
  next_dispatch = reinterpret_cast<PFN_vkCmdDispatch>(next_device_proc(*device, "vkCmdDispatch"));
  next_dispatch_base =
      reinterpret_cast<PFN_vkCmdDispatchBase>(next_device_proc(*device, "vkCmdDispatchBase"));
  const auto device_function = [&](const char* name) { return next_device_proc(*device, name); };
  next_buffer_requirements = reinterpret_cast<PFN_vkGetBufferMemoryRequirements>(
      device_function("vkGetBufferMemoryRequirements"));
  next_allocate = reinterpret_cast<PFN_vkAllocateMemory>(device_function("vkAllocateMemory"));
  next_map = reinterpret_cast<PFN_vkMapMemory>(device_function("vkMapMemory"));
  next_bind_buffer =
      reinterpret_cast<PFN_vkBindBufferMemory>(device_function("vkBindBufferMemory"));
  next_update_descriptors =
      reinterpret_cast<PFN_vkUpdateDescriptorSets>(device_function("vkUpdateDescriptorSets"));
  next_get_queue = reinterpret_cast<PFN_vkGetDeviceQueue>(device_function("vkGetDeviceQueue"));
  next_create_pool =
      reinterpret_cast<PFN_vkCreateCommandPool>(device_function("vkCreateCommandPool"));
  next_allocate_command_buffers =
      reinterpret_cast<PFN_vkAllocateCommandBuffers>(device_function("vkAllocateCommandBuffers"));
  next_create_buffer = reinterpret_cast<PFN_vkCreateBuffer>(device_function("vkCreateBuffer"));
  next_blit = reinterpret_cast<PFN_vkCmdBlitImage>(device_function("vkCmdBlitImage"));
  next_pipeline_barrier =
      reinterpret_cast<PFN_vkCmdPipelineBarrier>(device_function("vkCmdPipelineBarrier"));
  next_destroy_device = reinterpret_cast<PFN_vkDestroyDevice>(device_function("vkDestroyDevice"));
  next_queue_present =  // null without VK_KHR_swapchain
      reinterpret_cast<PFN_vkQueuePresentKHR>(next_device_proc(*device, "vkQueuePresentKHR"));
  return r;
}

VKAPI_ATTR VkResult VKAPI_CALL surface_support(VkPhysicalDevice physical, uint32_t family,
                                               VkSurfaceKHR surface, VkBool32* supported) {
  bool fake = false;
  if (fault_is("compute-queue-family")) {
    const std::lock_guard<std::mutex> lock(memory_mutex);
    const auto found = fake_family_of.find(physical);
    fake = found != fake_family_of.end() && family == found->second;
  }
  if (fault_is("no-present") || fake) {
    *supported = VK_FALSE;
    return VK_SUCCESS;
  }
  auto next = reinterpret_cast<PFN_vkGetPhysicalDeviceSurfaceSupportKHR>(
      next_instance_proc(created_instance, "vkGetPhysicalDeviceSurfaceSupportKHR"));
  return next(physical, family, surface, supported);
}

void disguise(VkPhysicalDeviceProperties& p) {
  p.deviceType = VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU;
  std::strncpy(p.deviceName, "rtvk disguised GPU", VK_MAX_PHYSICAL_DEVICE_NAME_SIZE);
}

void cap_workgroup_count(VkPhysicalDeviceProperties& p) {
  const long most = fault_count("workgroup-count");
  if (most <= 0) return;
  for (uint32_t& count : p.limits.maxComputeWorkGroupCount) count = uint32_t(most);
}

// A Vulkan 1.0 device has no vkGetPhysicalDeviceProperties2 or Features2: calling them for it is
// what crashes on a real one.
void refuse_on_vulkan_1_0(const char* call) {
  if (!fault_is("vulkan-1.0")) return;
  std::fprintf(stderr, "rtvk test layer: %s called for a Vulkan 1.0 device\n", call);
  std::abort();
}

VKAPI_ATTR void VKAPI_CALL device_properties(VkPhysicalDevice physical,
                                             VkPhysicalDeviceProperties* props) {
  next_properties(physical, props);
  cap_workgroup_count(*props);
  if (fault_is("vulkan-1.0")) props->apiVersion = VK_API_VERSION_1_0;
  if (fault_is("disguise-device")) disguise(*props);
}

VKAPI_ATTR void VKAPI_CALL device_properties2(VkPhysicalDevice physical,
                                              VkPhysicalDeviceProperties2* props) {
  refuse_on_vulkan_1_0("vkGetPhysicalDeviceProperties2");
  next_properties2(physical, props);
  cap_workgroup_count(props->properties);
  if (!fault_is("disguise-device")) return;
  disguise(props->properties);
  for (auto* s = static_cast<VkBaseOutStructure*>(props->pNext); s; s = s->pNext) {
    if (s->sType != VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES) continue;
    auto* driver = reinterpret_cast<VkPhysicalDeviceDriverProperties*>(s);
    driver->driverID = VK_DRIVER_ID_NVIDIA_PROPRIETARY;
    std::strncpy(driver->driverName, "NVIDIA", VK_MAX_DRIVER_NAME_SIZE);
    std::strncpy(driver->driverInfo, "555.42.02", VK_MAX_DRIVER_INFO_SIZE);
  }
}

VKAPI_ATTR void VKAPI_CALL device_features2(VkPhysicalDevice physical,
                                            VkPhysicalDeviceFeatures2* features) {
  refuse_on_vulkan_1_0("vkGetPhysicalDeviceFeatures2");
  next_features2(physical, features);
}

// compute-queue-family: the device's families and, last, one that computes and copies only.
void with_compute_family(VkPhysicalDevice physical, uint32_t* count,
                         VkQueueFamilyProperties* families) {
  uint32_t n = 0;
  next_queue_families(physical, &n, nullptr);
  std::vector<VkQueueFamilyProperties> all(n);
  next_queue_families(physical, &n, all.data());
  all.resize(n);
  VkQueueFamilyProperties compute = all.at(0);
  compute.queueFlags = VK_QUEUE_COMPUTE_BIT | VK_QUEUE_TRANSFER_BIT;
  compute.queueCount = 1;
  all.push_back(compute);
  {
    const std::lock_guard<std::mutex> lock(memory_mutex);
    fake_family_of[physical] = n;
  }
  if (!families) {
    *count = uint32_t(all.size());
    return;
  }
  *count = std::min<uint32_t>(*count, uint32_t(all.size()));
  std::copy(all.begin(), all.begin() + *count, families);
}

// The same for the Vulkan 1.1 query (the validation layer's): the fake family's extensions of
// the structure are left as the caller made them.
VKAPI_ATTR void VKAPI_CALL queue_families2(VkPhysicalDevice physical, uint32_t* count,
                                           VkQueueFamilyProperties2* families) {
  if (!fault_is("compute-queue-family")) return next_queue_families2(physical, count, families);
  uint32_t n = 0;
  next_queue_families2(physical, &n, nullptr);
  if (!families) {
    *count = n + 1;
    return;
  }
  std::vector<VkQueueFamilyProperties> plain(n + 1);
  uint32_t all = n + 1;
  with_compute_family(physical, &all, plain.data());
  uint32_t real = std::min(*count, n);
  next_queue_families2(physical, &real, families);
  *count = std::min(*count, n + 1);
  for (uint32_t k = real; k < *count; ++k) families[k].queueFamilyProperties = plain[k];
}

VKAPI_ATTR void VKAPI_CALL queue_families(VkPhysicalDevice physical, uint32_t* count,
                                          VkQueueFamilyProperties* families) {
  if (fault_is("compute-queue-family")) return with_compute_family(physical, count, families);
  next_queue_families(physical, count, families);
  if (!families || !fault_is("no-graphics-queue")) return;
  for (uint32_t k = 0; k < *count; ++k) families[k].queueFlags &= ~VK_QUEUE_GRAPHICS_BIT;
}

// discrete-memory: the device's own type that allocations of each fake type are made from, the
// first with the fake type's properties (lavapipe's one type has every property; a real discrete
// GPU has a device-local type and host types of its own), preferring one without the properties
// the fake type lacks.
void choose_real_types(VkPhysicalDevice physical) {
  VkPhysicalDeviceMemoryProperties m{};
  next_memory(physical, &m);
  const VkMemoryPropertyFlags local = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT,
                              host = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                     VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                              cached = VK_MEMORY_PROPERTY_HOST_CACHED_BIT;
  const auto pick = [&](VkMemoryPropertyFlags want, VkMemoryPropertyFlags rather_not) {
    for (const bool strict : {true, false})
      for (uint32_t t = 0; t < m.memoryTypeCount; ++t) {
        const VkMemoryPropertyFlags f = m.memoryTypes[t].propertyFlags;
        if ((f & want) == want && (!strict || (f & rather_not) == 0)) return t;
      }
    return uint32_t(0);
  };
  real_type_of_fake[0] = pick(local, host);
  real_type_of_fake[1] = pick(host, local);
  real_type_of_fake[2] = pick(host | cached, local);
  if ((m.memoryTypes[real_type_of_fake[2]].propertyFlags & host) != host)
    real_type_of_fake[2] = real_type_of_fake[1];  // no coherent cached type: plain host memory
}

// discrete-memory: a discrete GPU's memory types in place of the device's own.
void discrete_memory(VkPhysicalDeviceMemoryProperties& m) {
  const VkDeviceSize size = m.memoryHeaps[0].size;
  const VkMemoryPropertyFlags host =
      VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  m = VkPhysicalDeviceMemoryProperties{};
  m.memoryTypeCount = 3;
  m.memoryTypes[0] = {VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, 0};
  m.memoryTypes[1] = {host, 1};
  m.memoryTypes[2] = {host | VK_MEMORY_PROPERTY_HOST_CACHED_BIT, 1};
  m.memoryHeapCount = 2;
  m.memoryHeaps[0] = {size, VK_MEMORY_HEAP_DEVICE_LOCAL_BIT};
  m.memoryHeaps[1] = {size, 0};
}

VKAPI_ATTR void VKAPI_CALL memory_properties(VkPhysicalDevice physical,
                                             VkPhysicalDeviceMemoryProperties* m) {
  next_memory(physical, m);
  if (fault_is("discrete-memory")) discrete_memory(*m);
}

VKAPI_ATTR void VKAPI_CALL memory_properties2(VkPhysicalDevice physical,
                                              VkPhysicalDeviceMemoryProperties2* m) {
  const long budget_kib = fault_count("memory-budget");
  // The budget structure is this layer's to fill: the driver below may not know it.
  VkBaseOutStructure* budget = nullptr;
  if (budget_kib > 0) {
    for (auto* link = reinterpret_cast<VkBaseOutStructure*>(m); link->pNext; link = link->pNext)
      if (link->pNext->sType == VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MEMORY_BUDGET_PROPERTIES_EXT) {
        budget = link->pNext;
        link->pNext = budget->pNext;
        break;
      }
  }
  next_memory2(physical, m);
  if (fault_is("discrete-memory")) discrete_memory(m->memoryProperties);
  if (!budget) return;
  budget->pNext = static_cast<VkBaseOutStructure*>(m->pNext);
  m->pNext = budget;
  auto* b = reinterpret_cast<VkPhysicalDeviceMemoryBudgetPropertiesEXT*>(budget);
  for (uint32_t h = 0; h < VK_MAX_MEMORY_HEAPS; ++h) {
    b->heapBudget[h] = h < m->memoryProperties.memoryHeapCount ? VkDeviceSize(budget_kib) << 10 : 0;
    b->heapUsage[h] = 0;
  }
}

VKAPI_ATTR VkResult VKAPI_CALL device_extensions(VkPhysicalDevice physical, const char* layer,
                                                 uint32_t* count, VkExtensionProperties* props) {
  if (layer || fault_count("memory-budget") <= 0)
    return next_device_extensions(physical, layer, count, props);
  uint32_t n = 0;
  VkResult r = next_device_extensions(physical, nullptr, &n, nullptr);
  if (r != VK_SUCCESS) return r;
  std::vector<VkExtensionProperties> all(n);
  r = next_device_extensions(physical, nullptr, &n, all.data());
  if (r != VK_SUCCESS) return r;
  all.resize(n);
  bool has = false;
  for (const VkExtensionProperties& e : all)
    has = has || std::strcmp(e.extensionName, VK_EXT_MEMORY_BUDGET_EXTENSION_NAME) == 0;
  if (!has) {
    VkExtensionProperties e{};
    std::strncpy(e.extensionName, VK_EXT_MEMORY_BUDGET_EXTENSION_NAME, VK_MAX_EXTENSION_NAME_SIZE);
    e.specVersion = 1;
    all.push_back(e);
  }
  if (!props) {
    *count = uint32_t(all.size());
    return VK_SUCCESS;
  }
  const uint32_t copied = std::min<uint32_t>(*count, uint32_t(all.size()));
  std::memcpy(props, all.data(), copied * sizeof(VkExtensionProperties));
  *count = copied;
  return copied < all.size() ? VK_INCOMPLETE : VK_SUCCESS;
}

VKAPI_ATTR void VKAPI_CALL buffer_requirements(VkDevice device, VkBuffer buffer,
                                               VkMemoryRequirements* req) {
  next_buffer_requirements(device, buffer, req);
  if (fault_is("discrete-memory")) req->memoryTypeBits = 0b111;
}

VKAPI_ATTR VkResult VKAPI_CALL allocate_memory(VkDevice device, const VkMemoryAllocateInfo* info,
                                               const VkAllocationCallbacks* allocator,
                                               VkDeviceMemory* memory) {
  if (!fault_is("discrete-memory")) return next_allocate(device, info, allocator, memory);
  VkMemoryAllocateInfo real = *info;
  real.memoryTypeIndex = real_type_of_fake[std::min(info->memoryTypeIndex, 2u)];
  const VkResult r = next_allocate(device, &real, allocator, memory);
  if (r != VK_SUCCESS) return r;
  const std::lock_guard<std::mutex> lock(memory_mutex);
  memory_type_of[std::uint64_t(*memory)] = info->memoryTypeIndex;
  return r;
}

VKAPI_ATTR VkResult VKAPI_CALL map_memory(VkDevice device, VkDeviceMemory memory,
                                          VkDeviceSize offset, VkDeviceSize size,
                                          VkMemoryMapFlags flags, void** data) {
  if (fault_is("discrete-memory")) {
    const std::lock_guard<std::mutex> lock(memory_mutex);
    if (memory_type_of[std::uint64_t(memory)] == 0) {
      std::fprintf(stderr, "rtvk test layer: vkMapMemory of device-local memory\n");
      return VK_ERROR_MEMORY_MAP_FAILED;
    }
  }
  return next_map(device, memory, offset, size, flags, data);
}

VKAPI_ATTR VkResult VKAPI_CALL bind_buffer(VkDevice device, VkBuffer buffer, VkDeviceMemory memory,
                                           VkDeviceSize offset) {
  if (fault_is("discrete-memory")) {
    const std::lock_guard<std::mutex> lock(memory_mutex);
    memory_of_buffer[std::uint64_t(buffer)] = std::uint64_t(memory);
  }
  return next_bind_buffer(device, buffer, memory, offset);
}

VKAPI_ATTR void VKAPI_CALL update_descriptors(VkDevice device, uint32_t count,
                                              const VkWriteDescriptorSet* writes, uint32_t copies,
                                              const VkCopyDescriptorSet* copy) {
  if (fault_is("discrete-memory")) {
    const std::lock_guard<std::mutex> lock(memory_mutex);
    for (uint32_t w = 0; w < count; ++w) {
      const VkDescriptorType t = writes[w].descriptorType;
      if (t != VK_DESCRIPTOR_TYPE_STORAGE_BUFFER && t != VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER)
        continue;
      for (uint32_t k = 0; k < writes[w].descriptorCount; ++k) {
        const std::uint64_t memory =
            memory_of_buffer[std::uint64_t(writes[w].pBufferInfo[k].buffer)];
        if (memory_type_of[memory] != 0 && !shader_reads_host_memory.exchange(true))
          std::fprintf(stderr,
                       "rtvk test layer: binding %u reads a buffer in host memory (type %u)\n",
                       writes[w].dstBinding, memory_type_of[memory]);
      }
    }
  }
  next_update_descriptors(device, count, writes, copies, copy);
}

// The device's own queue behind a handle this layer gave out.
VkQueue real_queue(VkQueue queue) {
  return queue == reinterpret_cast<VkQueue>(fake_queue_object) ? real_queue_behind_fake : queue;
}

VKAPI_ATTR void VKAPI_CALL get_device_queue(VkDevice device, uint32_t family, uint32_t index,
                                            VkQueue* queue) {
  if (!fault_is("compute-queue-family") || family != fake_family) {
    next_get_queue(device, family, index, queue);
    const VkQueueFlags f = family < real_families.size() ? real_families[family].queueFlags : 0;
    if ((f & VK_QUEUE_COMPUTE_BIT) && !(f & VK_QUEUE_GRAPHICS_BIT)) {
      const std::lock_guard<std::mutex> lock(memory_mutex);
      compute_only_queues.push_back(*queue);
    }
    return;
  }
  next_get_queue(device, 0, 0, &real_queue_behind_fake);
  // The loader writes its dispatch pointer (the device's) into the queues its vkGetDeviceQueue
  // returns, and the layers below look their state up by it: the real queue never goes back
  // through the loader, so it is written here, and the fake one's until the loader writes it.
  *reinterpret_cast<void**>(real_queue_behind_fake) = *reinterpret_cast<void**>(device);
  fake_queue_object[0] = *reinterpret_cast<void**>(device);
  *queue = reinterpret_cast<VkQueue>(fake_queue_object);
}

VKAPI_ATTR VkResult VKAPI_CALL create_command_pool(VkDevice device,
                                                   const VkCommandPoolCreateInfo* info,
                                                   const VkAllocationCallbacks* allocator,
                                                   VkCommandPool* pool) {
  const bool fake = fault_is("compute-queue-family") && info->queueFamilyIndex == fake_family;
  VkCommandPoolCreateInfo real = *info;
  if (fake) real.queueFamilyIndex = 0;
  const VkResult r = next_create_pool(device, &real, allocator, pool);
  if (r != VK_SUCCESS) return r;
  const std::lock_guard<std::mutex> lock(memory_mutex);
  pool_is_fake[std::uint64_t(*pool)] = fake;
  return r;
}

VKAPI_ATTR VkResult VKAPI_CALL allocate_command_buffers(VkDevice device,
                                                        const VkCommandBufferAllocateInfo* info,
                                                        VkCommandBuffer* cbs) {
  const VkResult r = next_allocate_command_buffers(device, info, cbs);
  if (r != VK_SUCCESS) return r;
  const std::lock_guard<std::mutex> lock(memory_mutex);
  for (uint32_t k = 0; k < info->commandBufferCount; ++k)
    cb_is_fake[cbs[k]] = pool_is_fake[std::uint64_t(info->commandPool)];
  return r;
}

// A family index as the device knows it.
uint32_t real_family(uint32_t family) {
  return fault_is("compute-queue-family") && family == fake_family ? 0 : family;
}

VKAPI_ATTR VkResult VKAPI_CALL create_buffer(VkDevice device, const VkBufferCreateInfo* info,
                                             const VkAllocationCallbacks* allocator,
                                             VkBuffer* buffer) {
  if (info->sharingMode != VK_SHARING_MODE_CONCURRENT)
    return next_create_buffer(device, info, allocator, buffer);
  std::vector<uint32_t> families;
  for (uint32_t k = 0; k < info->queueFamilyIndexCount; ++k) {
    const uint32_t f = real_family(info->pQueueFamilyIndices[k]);
    if (std::find(families.begin(), families.end(), f) == families.end()) families.push_back(f);
  }
  VkBufferCreateInfo real = *info;
  real.queueFamilyIndexCount = uint32_t(families.size());
  real.pQueueFamilyIndices = families.data();
  if (families.size() < 2) {  // one family underneath: exclusive, as the device requires
    real.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    real.queueFamilyIndexCount = 0;
    real.pQueueFamilyIndices = nullptr;
  }
  return next_create_buffer(device, &real, allocator, buffer);
}

void graphics_command(VkCommandBuffer cb, const char* call) {
  bool fake = false;
  {
    const std::lock_guard<std::mutex> lock(memory_mutex);
    fake = cb_is_fake[cb];
  }
  if (fake && !graphics_on_compute_queue.exchange(true))
    std::fprintf(stderr, "rtvk test layer: %s recorded for the compute-only queue family\n", call);
}

VKAPI_ATTR void VKAPI_CALL blit_image(VkCommandBuffer cb, VkImage src, VkImageLayout src_layout,
                                      VkImage dst, VkImageLayout dst_layout, uint32_t count,
                                      const VkImageBlit* regions, VkFilter filter) {
  graphics_command(cb, "vkCmdBlitImage");
  next_blit(cb, src, src_layout, dst, dst_layout, count, regions, filter);
}

VKAPI_ATTR void VKAPI_CALL pipeline_barrier(VkCommandBuffer cb, VkPipelineStageFlags src,
                                            VkPipelineStageFlags dst, VkDependencyFlags flags,
                                            uint32_t memory_count, const VkMemoryBarrier* memory,
                                            uint32_t buffer_count,
                                            const VkBufferMemoryBarrier* buffers,
                                            uint32_t image_count,
                                            const VkImageMemoryBarrier* images) {
  std::vector<VkBufferMemoryBarrier> b(buffers, buffers + buffer_count);
  std::vector<VkImageMemoryBarrier> i(images, images + image_count);
  for (auto& x : b) {
    x.srcQueueFamilyIndex = real_family(x.srcQueueFamilyIndex);
    x.dstQueueFamilyIndex = real_family(x.dstQueueFamilyIndex);
  }
  for (auto& x : i) {
    x.srcQueueFamilyIndex = real_family(x.srcQueueFamilyIndex);
    x.dstQueueFamilyIndex = real_family(x.dstQueueFamilyIndex);
  }
  next_pipeline_barrier(cb, src, dst, flags, memory_count, memory, buffer_count, b.data(),
                        image_count, i.data());
}

VKAPI_ATTR void VKAPI_CALL destroy_device(VkDevice device, const VkAllocationCallbacks* allocator) {
  if (fault_is("compute-queue-family"))
    std::fprintf(stderr,
                 "rtvk test layer: submissions: %ld to compute-only families, %ld to the others\n",
                 long(fake_submits), long(real_submits));
  next_destroy_device(device, allocator);
}

VKAPI_ATTR VkResult VKAPI_CALL queue_submit(VkQueue queue, uint32_t count,
                                            const VkSubmitInfo* submits_info, VkFence fence) {
  bool compute_only = queue == reinterpret_cast<VkQueue>(fake_queue_object);
  {
    const std::lock_guard<std::mutex> lock(memory_mutex);
    compute_only = compute_only || std::find(compute_only_queues.begin(), compute_only_queues.end(),
                                             queue) != compute_only_queues.end();
  }
  ++(compute_only ? fake_submits : real_submits);
  queue = real_queue(queue);
  if (graphics_on_compute_queue) return VK_ERROR_DEVICE_LOST;
  const long at = fault_count("lose-device-at-submit");
  const long after = fault_count("lose-device-after-present");
  if ((at > 0 && ++submits >= at) || (after > 0 && presents >= after)) return VK_ERROR_DEVICE_LOST;
  if (dispatched_past_limit || shader_reads_host_memory) return VK_ERROR_DEVICE_LOST;
  const long watchdog_us =
      fault_count("watchdog") > 0 ? fault_count("watchdog") * 1000 : fault_count("watchdog-us");
  if (watchdog_us <= 0) return next_queue_submit(queue, count, submits_info, fence);
  if (watchdog_fired) return VK_ERROR_DEVICE_LOST;
  // Whatever ran before this submission is done (each is waited for here), so the time from the
  // call to an idle queue is this submission's alone.
  const auto start = std::chrono::steady_clock::now();
  const VkResult r = next_queue_submit(queue, count, submits_info, fence);
  if (r != VK_SUCCESS) return r;
  const VkResult idle = next_queue_wait_idle(queue);
  if (idle != VK_SUCCESS) return idle;
  const auto us = std::chrono::duration_cast<std::chrono::microseconds>(
                      std::chrono::steady_clock::now() - start)
                      .count();
  if (us <= watchdog_us) return VK_SUCCESS;
  watchdog_fired = true;
  std::fprintf(stderr,
               "rtvk test layer: a submission kept the queue busy for %ld us (watchdog: %ld us)\n",
               long(us), watchdog_us);
  return VK_ERROR_DEVICE_LOST;
}

void check_workgroup_count(uint32_t x, uint32_t y, uint32_t z) {
  const long most = fault_count("workgroup-count");
  if (most <= 0 || (x <= uint32_t(most) && y <= uint32_t(most) && z <= uint32_t(most))) return;
  if (!dispatched_past_limit.exchange(true))
    std::fprintf(stderr, "rtvk test layer: a dispatch of %u x %u x %u workgroups (limit: %ld)\n", x,
                 y, z, most);
}

VKAPI_ATTR void VKAPI_CALL dispatch(VkCommandBuffer cb, uint32_t x, uint32_t y, uint32_t z) {
  check_workgroup_count(x, y, z);
  next_dispatch(cb, x, y, z);
}

VKAPI_ATTR void VKAPI_CALL dispatch_base(VkCommandBuffer cb, uint32_t bx, uint32_t by, uint32_t bz,
                                         uint32_t x, uint32_t y, uint32_t z) {
  check_workgroup_count(x, y, z);
  next_dispatch_base(cb, bx, by, bz, x, y, z);
}

VKAPI_ATTR VkResult VKAPI_CALL queue_present(VkQueue queue, const VkPresentInfoKHR* info) {
  ++presents;
  if (queue == reinterpret_cast<VkQueue>(fake_queue_object)) {
    std::fprintf(stderr, "rtvk test layer: vkQueuePresentKHR from the compute-only queue family\n");
    graphics_on_compute_queue = true;
    return VK_ERROR_DEVICE_LOST;
  }
  return next_queue_present(queue, info);
}

VKAPI_ATTR VkResult VKAPI_CALL queue_wait_idle(VkQueue queue) {
  return next_queue_wait_idle(real_queue(queue));
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL get_device_proc(VkDevice device, const char* name);

// The functions this layer changes, by name; null for the others.
PFN_vkVoidFunction own_function(const char* name) {
  const auto is = [name](const char* n) { return std::strcmp(name, n) == 0; };
  if (is("vkGetDeviceProcAddr")) return reinterpret_cast<PFN_vkVoidFunction>(get_device_proc);
  if (is("vkCreateDevice")) return reinterpret_cast<PFN_vkVoidFunction>(create_device);
  if (is("vkQueueSubmit")) return reinterpret_cast<PFN_vkVoidFunction>(queue_submit);
  if (is("vkQueuePresentKHR")) return reinterpret_cast<PFN_vkVoidFunction>(queue_present);
  if (is("vkCmdDispatch")) return reinterpret_cast<PFN_vkVoidFunction>(dispatch);
  if (is("vkGetDeviceQueue")) return reinterpret_cast<PFN_vkVoidFunction>(get_device_queue);
  if (is("vkQueueWaitIdle")) return reinterpret_cast<PFN_vkVoidFunction>(queue_wait_idle);
  if (is("vkCreateCommandPool")) return reinterpret_cast<PFN_vkVoidFunction>(create_command_pool);
  if (is("vkAllocateCommandBuffers"))
    return reinterpret_cast<PFN_vkVoidFunction>(allocate_command_buffers);
  if (is("vkCreateBuffer")) return reinterpret_cast<PFN_vkVoidFunction>(create_buffer);
  if (is("vkCmdBlitImage")) return reinterpret_cast<PFN_vkVoidFunction>(blit_image);
  if (is("vkCmdPipelineBarrier")) return reinterpret_cast<PFN_vkVoidFunction>(pipeline_barrier);
  if (is("vkDestroyDevice")) return reinterpret_cast<PFN_vkVoidFunction>(destroy_device);
  if (is("vkGetBufferMemoryRequirements"))
    return reinterpret_cast<PFN_vkVoidFunction>(buffer_requirements);
  if (is("vkAllocateMemory")) return reinterpret_cast<PFN_vkVoidFunction>(allocate_memory);
  if (is("vkMapMemory")) return reinterpret_cast<PFN_vkVoidFunction>(map_memory);
  if (is("vkBindBufferMemory")) return reinterpret_cast<PFN_vkVoidFunction>(bind_buffer);
  if (is("vkUpdateDescriptorSets")) return reinterpret_cast<PFN_vkVoidFunction>(update_descriptors);
  if (is("vkCmdDispatchBase") || is("vkCmdDispatchBaseKHR"))
    return reinterpret_cast<PFN_vkVoidFunction>(dispatch_base);
  return nullptr;
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL get_instance_proc(VkInstance instance, const char* name) {
  const auto is = [name](const char* n) { return std::strcmp(name, n) == 0; };
  if (is("vkGetInstanceProcAddr")) return reinterpret_cast<PFN_vkVoidFunction>(get_instance_proc);
  if (is("vkCreateInstance")) return reinterpret_cast<PFN_vkVoidFunction>(create_instance);
  if (is("vkGetPhysicalDeviceSurfaceSupportKHR"))
    return reinterpret_cast<PFN_vkVoidFunction>(surface_support);
  if (is("vkGetPhysicalDeviceProperties"))
    return reinterpret_cast<PFN_vkVoidFunction>(device_properties);
  if (is("vkGetPhysicalDeviceProperties2") || is("vkGetPhysicalDeviceProperties2KHR"))
    return reinterpret_cast<PFN_vkVoidFunction>(device_properties2);
  if (is("vkGetPhysicalDeviceFeatures2") || is("vkGetPhysicalDeviceFeatures2KHR"))
    return reinterpret_cast<PFN_vkVoidFunction>(device_features2);
  if (is("vkGetPhysicalDeviceQueueFamilyProperties"))
    return reinterpret_cast<PFN_vkVoidFunction>(queue_families);
  if (is("vkGetPhysicalDeviceQueueFamilyProperties2") ||
      is("vkGetPhysicalDeviceQueueFamilyProperties2KHR"))
    return reinterpret_cast<PFN_vkVoidFunction>(queue_families2);
  if (is("vkGetPhysicalDeviceMemoryProperties"))
    return reinterpret_cast<PFN_vkVoidFunction>(memory_properties);
  if (is("vkGetPhysicalDeviceMemoryProperties2") || is("vkGetPhysicalDeviceMemoryProperties2KHR"))
    return reinterpret_cast<PFN_vkVoidFunction>(memory_properties2);
  if (is("vkEnumerateDeviceExtensionProperties"))
    return reinterpret_cast<PFN_vkVoidFunction>(device_extensions);
  if (PFN_vkVoidFunction own = own_function(name)) return own;
  return next_instance_proc ? next_instance_proc(instance, name) : nullptr;
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL get_device_proc(VkDevice device, const char* name) {
  if (PFN_vkVoidFunction own = own_function(name)) {
    // A device without the swapchain extension has no present to pass on to.
    if (std::strcmp(name, "vkQueuePresentKHR") == 0 && !next_queue_present) return nullptr;
    return own;
  }
  return next_device_proc ? next_device_proc(device, name) : nullptr;
}

}  // namespace

extern "C" VK_LAYER_EXPORT VKAPI_ATTR VkResult VKAPI_CALL
vkNegotiateLoaderLayerInterfaceVersion(VkNegotiateLayerInterface* v) {
  if (v->loaderLayerInterfaceVersion < 2) return VK_ERROR_INITIALIZATION_FAILED;
  v->loaderLayerInterfaceVersion = 2;
  v->pfnGetInstanceProcAddr = get_instance_proc;
  v->pfnGetDeviceProcAddr = get_device_proc;
  v->pfnGetPhysicalDeviceProcAddr = nullptr;
  return VK_SUCCESS;
}
