// A Vulkan layer for tests: every device it sees answers that no queue can present to any
// surface (vkGetPhysicalDeviceSurfaceSupportKHR says VK_FALSE); everything else passes through.
// With it, a test can show rtvk view a device that cannot present to its window. The chain is
// kept in globals: a test process of rtvk makes one instance and at most one device.
#include <vulkan/vk_layer.h>

#include <cstring>

namespace {

PFN_vkGetInstanceProcAddr next_instance_proc = nullptr;  // the next layer's, or the loader's
PFN_vkGetDeviceProcAddr next_device_proc = nullptr;
VkInstance created_instance = VK_NULL_HANDLE;  // rtvk makes one at a time

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
  if (r == VK_SUCCESS) created_instance = *instance;
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
  return create(physical, info, allocator, device);
}

VKAPI_ATTR VkResult VKAPI_CALL surface_support(VkPhysicalDevice, uint32_t, VkSurfaceKHR,
                                               VkBool32* supported) {
  *supported = VK_FALSE;
  return VK_SUCCESS;
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL get_device_proc(VkDevice device, const char* name);

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL get_instance_proc(VkInstance instance, const char* name) {
  const auto is = [name](const char* n) { return std::strcmp(name, n) == 0; };
  if (is("vkGetInstanceProcAddr")) return reinterpret_cast<PFN_vkVoidFunction>(get_instance_proc);
  if (is("vkGetDeviceProcAddr")) return reinterpret_cast<PFN_vkVoidFunction>(get_device_proc);
  if (is("vkCreateInstance")) return reinterpret_cast<PFN_vkVoidFunction>(create_instance);
  if (is("vkCreateDevice")) return reinterpret_cast<PFN_vkVoidFunction>(create_device);
  if (is("vkGetPhysicalDeviceSurfaceSupportKHR"))
    return reinterpret_cast<PFN_vkVoidFunction>(surface_support);
  return next_instance_proc ? next_instance_proc(instance, name) : nullptr;
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL get_device_proc(VkDevice device, const char* name) {
  if (std::strcmp(name, "vkGetDeviceProcAddr") == 0)
    return reinterpret_cast<PFN_vkVoidFunction>(get_device_proc);
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
