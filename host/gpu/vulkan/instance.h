#pragma once
#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include "vk_handle.h"

namespace rtvk::gpu {

// The Vulkan instance, with VK_LAYER_KHRONOS_validation and a debug messenger when asked.
// Validation warnings and errors go to stderr as "validation: ..." and are counted, so tests
// can fail on any of them.
class vulkan_instance {
 public:
  // Throws no_device_error when there is no Vulkan loader or no Vulkan 1.1 implementation.
  // `extensions`: instance extensions to enable besides rtvk's own (a window system's surface).
  explicit vulkan_instance(bool validate, const std::vector<std::string>& extensions = {});
  vulkan_instance(const vulkan_instance&) = delete;
  vulkan_instance& operator=(const vulkan_instance&) = delete;

  VkInstance get() const { return instance_.get(); }
  bool validating() const { return validating_; }
  // Gives the instance up without destroying it: the driver may still be running work for it.
  void abandon() {
    messenger_.release();
    instance_.release();
  }

  // Validation-layer messages of WARNING or ERROR severity so far.
  std::uint32_t validation_messages() const { return messages_.load(); }

 private:
  // Destroyed in reverse order: messenger, instance; the counter outlives both.
  bool validating_ = false;                 // the layer and messenger are enabled
  std::atomic<std::uint32_t> messages_{0};  // warnings and errors reported by the layer
  unique_instance instance_;                // the instance itself
  unique_messenger messenger_;              // routes layer messages to stderr
};

}  // namespace rtvk::gpu
