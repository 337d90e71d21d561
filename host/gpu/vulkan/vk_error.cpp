#include "vk_error.h"

namespace rtvk::gpu {

std::string result_name(VkResult r) {
  switch (r) {
#define RTVK_RESULT(name) \
  case name:              \
    return #name;
    RTVK_RESULT(VK_SUCCESS)
    RTVK_RESULT(VK_NOT_READY)
    RTVK_RESULT(VK_TIMEOUT)
    RTVK_RESULT(VK_EVENT_SET)
    RTVK_RESULT(VK_EVENT_RESET)
    RTVK_RESULT(VK_INCOMPLETE)
    RTVK_RESULT(VK_ERROR_OUT_OF_HOST_MEMORY)
    RTVK_RESULT(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    RTVK_RESULT(VK_ERROR_INITIALIZATION_FAILED)
    RTVK_RESULT(VK_ERROR_DEVICE_LOST)
    RTVK_RESULT(VK_ERROR_MEMORY_MAP_FAILED)
    RTVK_RESULT(VK_ERROR_LAYER_NOT_PRESENT)
    RTVK_RESULT(VK_ERROR_EXTENSION_NOT_PRESENT)
    RTVK_RESULT(VK_ERROR_FEATURE_NOT_PRESENT)
    RTVK_RESULT(VK_ERROR_INCOMPATIBLE_DRIVER)
    RTVK_RESULT(VK_ERROR_TOO_MANY_OBJECTS)
    RTVK_RESULT(VK_ERROR_FORMAT_NOT_SUPPORTED)
    RTVK_RESULT(VK_ERROR_FRAGMENTED_POOL)
    RTVK_RESULT(VK_ERROR_UNKNOWN)
    RTVK_RESULT(VK_ERROR_OUT_OF_POOL_MEMORY)
    RTVK_RESULT(VK_ERROR_INVALID_EXTERNAL_HANDLE)
    RTVK_RESULT(VK_ERROR_FRAGMENTATION)
    RTVK_RESULT(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
    RTVK_RESULT(VK_PIPELINE_COMPILE_REQUIRED)
    RTVK_RESULT(VK_ERROR_VALIDATION_FAILED_EXT)
#undef RTVK_RESULT
    default:
      return "VkResult(" + std::to_string(int(r)) + ")";
  }
}

no_device_error::no_device_error(const std::string& what)
    : std::runtime_error(what +
                         ": install a Vulkan driver (apt-get install mesa-vulkan-drivers provides "
                         "lavapipe, which runs on any CPU) or use --backend cpu") {}

}  // namespace rtvk::gpu
