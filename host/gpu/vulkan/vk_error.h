#pragma once
#include <volk.h>

#include <stdexcept>
#include <string>

namespace rtvk::gpu {

// The symbolic name of a VkResult ("VK_ERROR_DEVICE_LOST"), or its number when unknown.
std::string result_name(VkResult r);

// A Vulkan call failed: the message names the call and its result.
class vk_error : public std::runtime_error {
 public:
  vk_error(const std::string& call, VkResult r, const std::string& detail = "")
      : std::runtime_error(call + ": " + result_name(r) +
                           (detail.empty() ? "" : " (" + detail + ")")),
        result(r) {}
  VkResult result;  // what the call returned
};

// No usable Vulkan device (or no loader) on this machine: `--backend auto` falls back to the CPU.
class no_device_error : public std::runtime_error {
 public:
  explicit no_device_error(const std::string& what);
};

inline void vk_check(VkResult r, const char* call) {
  if (r != VK_SUCCESS) throw vk_error(call, r);
}

}  // namespace rtvk::gpu
