#pragma once
#include <volk.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace rtvk::gpu {

// What rtvk knows about one Vulkan device, as `rtvk devices` lists it.
struct device_info {
  std::uint32_t index = 0;  // position in vkEnumeratePhysicalDevices
  VkPhysicalDevice handle = VK_NULL_HANDLE;
  std::string name;  // deviceName
  VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
  std::uint32_t vendor_id = 0;             // PCI vendor ID
  std::string driver_name;                 // from VkPhysicalDeviceDriverProperties, or empty
  std::string driver_info;                 // ditto
  std::uint32_t driver_version = 0;        // vendor-encoded
  std::uint32_t api_version = 0;           // highest Vulkan version the device supports
  std::uint32_t compute_queue_family = 0;  // first family with compute, when usable
  std::uint32_t timestamp_valid_bits = 0;  // of that family's timestamps; 0: it has none
  std::uint32_t subgroup_size = 1;         // invocations that run in lockstep (a warp, a wave)
  std::string unusable_reason;             // empty when rtvk can render on it
  VkPhysicalDeviceLimits limits{};         // for workgroup and buffer sizes
  VkDeviceSize max_allocation_size = 0;    // largest single allocation (Vulkan 1.1's
                                           // maintenance3); 0 when the device does not say
};

std::vector<device_info> list_devices(VkInstance instance);

// Whether the device offers the named extension.
bool has_device_extension(VkPhysicalDevice dev, const char* name);

std::string type_name(VkPhysicalDeviceType type);       // "discrete", "cpu", ...
std::string version_string(std::uint32_t api_version);  // "1.3.230"
std::string driver_version_string(const device_info& d);

// The device rtvk picks without --device: discrete > integrated > virtual > cpu > other, among
// usable devices, first listed on a tie. Throws no_device_error when none is usable.
std::size_t default_device(const std::vector<device_info>& devices);

// --device: an index ("0") or a case-insensitive substring of the name ("llvmpipe"); empty picks
// the default. Throws usage_error, listing the devices, when nothing (usable) matches.
std::size_t select_device(const std::vector<device_info>& devices, const std::string& selector);

// One line per device, the chosen one marked with '*'.
std::string describe_devices(const std::vector<device_info>& devices, std::size_t chosen);

}  // namespace rtvk::gpu
