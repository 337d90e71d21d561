#pragma once
#include <cstdint>
#include <memory>

#include "buffer.h"
#include "context.h"
#include "vk_handle.h"

namespace rtvk::gpu {

// The device address of a buffer made with VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT.
VkDeviceAddress device_address(const gpu_context& ctx, VkBuffer buffer);

// The device's acceleration-structure limits (VkPhysicalDeviceAccelerationStructurePropertiesKHR),
// maxPrimitiveCount within the context's caps.
VkPhysicalDeviceAccelerationStructurePropertiesKHR acceleration_limits(const gpu_context& ctx);

// One acceleration structure (a bottom or top level) with the device-local buffer it lives in.
class acceleration_structure {
 public:
  acceleration_structure(const gpu_context& ctx, VkAccelerationStructureTypeKHR type,
                         VkDeviceSize bytes);
  ~acceleration_structure();
  acceleration_structure(const acceleration_structure&) = delete;
  acceleration_structure& operator=(const acceleration_structure&) = delete;

  VkAccelerationStructureKHR get() const { return handle_.get(); }
  VkDeviceAddress address() const { return address_; }  // for a top level's instances
  VkDeviceSize bytes() const { return storage_.size(); }

 private:
  const gpu_context& ctx_;  // tells whether the device may still be using it
  gpu_buffer storage_;      // where the driver keeps it
  unique_acceleration_structure handle_;
  VkDeviceAddress address_ = 0;
};

}  // namespace rtvk::gpu
