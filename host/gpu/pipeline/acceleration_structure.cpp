#include "acceleration_structure.h"

#include "vk_error.h"

namespace rtvk::gpu {

VkDeviceAddress device_address(const gpu_context& ctx, VkBuffer buffer) {
  VkBufferDeviceAddressInfo info{VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO};
  info.buffer = buffer;
  return vkGetBufferDeviceAddressKHR(ctx.vk(), &info);
}

VkPhysicalDeviceAccelerationStructurePropertiesKHR acceleration_limits(const gpu_context& ctx) {
  VkPhysicalDeviceAccelerationStructurePropertiesKHR as{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_PROPERTIES_KHR};
  VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  props.pNext = &as;
  vkGetPhysicalDeviceProperties2(ctx.device().handle, &props);
  const std::uint64_t cap = ctx.caps().primitives;  // tests only
  if (cap != 0 && cap < as.maxPrimitiveCount) as.maxPrimitiveCount = cap;
  return as;
}

acceleration_structure::acceleration_structure(const gpu_context& ctx,
                                               VkAccelerationStructureTypeKHR type,
                                               VkDeviceSize bytes)
    : ctx_(ctx),
      storage_(ctx, bytes,
               VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR |
                   VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
               memory_use::device_local) {
  VkAccelerationStructureCreateInfoKHR info{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR};
  info.buffer = storage_.get();
  info.size = bytes;
  info.type = type;
  VkAccelerationStructureKHR as = VK_NULL_HANDLE;
  vk_check(vkCreateAccelerationStructureKHR(ctx.vk(), &info, nullptr, &as),
           "vkCreateAccelerationStructureKHR");
  handle_ = unique_acceleration_structure(ctx.vk(), as);
  VkAccelerationStructureDeviceAddressInfoKHR at{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR};
  at.accelerationStructure = as;
  address_ = vkGetAccelerationStructureDeviceAddressKHR(ctx.vk(), &at);
}

acceleration_structure::~acceleration_structure() {
  if (ctx_.lost()) handle_.release();  // a hung device may still read it
}

}  // namespace rtvk::gpu
