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
  std::uint32_t device_id = 0;             // vendor's device ID
  VkDriverId driver_id = VkDriverId(0);    // from VkPhysicalDeviceDriverProperties; 0: unknown
  std::string driver_name;                 // ditto ("llvmpipe", "NVIDIA", "radv"), or empty
  std::string driver_info;                 // ditto ("Mesa 25.0.7", "550.54.14"), or empty
  std::uint32_t driver_version = 0;        // vendor-encoded
  std::uint32_t api_version = 0;           // highest Vulkan version the device supports
  std::uint32_t compute_queue_family = 0;  // the family rtvk submits to (use_queue_family)
  std::uint32_t timestamp_valid_bits = 0;  // of that family's timestamps; 0: it has none
  std::vector<VkQueueFamilyProperties> queue_families;  // as the device lists them
  std::uint32_t subgroup_size = 1;       // invocations that run in lockstep (a warp, a wave)
  std::string unusable_reason;           // empty when rtvk can render on it
  VkPhysicalDeviceLimits limits{};       // for workgroup and buffer sizes
  VkDeviceSize max_allocation_size = 0;  // largest single allocation (Vulkan 1.1's
                                         // maintenance3); 0 when the device does not say
  bool acceleration_structures = false;  // VK_KHR_acceleration_structure, extension and feature
  bool ray_queries = false;              // VK_KHR_ray_query, ditto
  bool ray_tracing_pipelines = false;    // VK_KHR_ray_tracing_pipeline, ditto
  std::uint8_t pipeline_cache_uuid[VK_UUID_SIZE] = {};  // the driver's cache compatibility
  std::uint8_t driver_uuid[VK_UUID_SIZE] = {};  // the driver build (Vulkan 1.1); 0s: unknown
};

// Whether the driver compiles a pipeline's shaders in the first submission that runs it rather
// than in vkCreate*Pipelines: lavapipe, known by its driver ID (VK_DRIVER_ID_MESA_LLVMPIPE), never
// by its name. That submission may take minutes (gpu_context::first_run_allowance).
inline bool compiles_in_first_run(const device_info& d) {
  return d.driver_id == VK_DRIVER_ID_MESA_LLVMPIPE;
}

// No queue family: the device has none of the kind asked for.
inline constexpr std::uint32_t no_queue_family = ~0u;

// Every device the instance offers. Each one's compute_queue_family is a compute-only family
// where it has one (asynchronous compute: rendering there does not hold up the desktop's
// drawing), else its first family with compute.
std::vector<device_info> list_devices(VkInstance instance);

// The family rtvk computes on: one with compute and no graphics where the device has one (AMD's
// and NVIDIA's asynchronous compute queues), else the first with compute; no_queue_family if none.
std::uint32_t compute_family(const std::vector<VkQueueFamilyProperties>& families);

// Makes `family` the one rtvk submits to (and times with).
void use_queue_family(device_info& d, std::uint32_t family);

// The device extensions hardware ray tracing needs, those of them the device lists: acceleration
// structures and what they build on (device addresses, deferred host operations, descriptor
// indexing; SPIR-V 1.4 and float controls for the shaders), ray queries, ray-tracing pipelines.
std::vector<const char*> ray_tracing_extensions(const device_info& d);
// Why the device cannot take a hardware path (`pipelines`: ray-tracing pipelines, else ray
// queries): the first extension it lacks, or its feature that is off; empty when it can.
std::string missing_ray_tracing(const device_info& d, bool pipelines);

// Whether the device offers the named extension.
bool has_device_extension(VkPhysicalDevice dev, const char* name);

std::string type_name(VkPhysicalDeviceType type);       // "discrete", "cpu", ...
std::string version_string(std::uint32_t api_version);  // "1.3.230"
std::string driver_version_string(const device_info& d);

// The name people know the driver by, from its driver ID ("lavapipe", "radv", "anv", "nvidia"),
// or empty for an ID this table does not know.
std::string driver_common_name(VkDriverId id);

// The driver as `rtvk devices` shows it: "lavapipe (llvmpipe), Mesa 25.0.7 (LLVM 15.0.6)".
std::string driver_string(const device_info& d);

// The device rtvk picks without --device: discrete > integrated > virtual > cpu > other, among
// usable devices, first listed on a tie. Throws no_device_error when none is usable.
std::size_t default_device(const std::vector<device_info>& devices);

// --device: an index ("0"), or a case-insensitive substring of the device's name ("RTX 4090"),
// of its driver's name, common name or version ("llvmpipe", "lavapipe", "radv", "Mesa 25");
// the first usable device that matches. Empty picks the default. Throws no_device_error when there
// is no device at all, and usage_error naming `source` (the flag or variable the selector came
// from), listing the devices, when nothing matches or the match is unusable.
std::size_t select_device(const std::vector<device_info>& devices, const std::string& selector,
                          const std::string& source = "--device");

// One line: "0: llvmpipe (LLVM 15.0.6, 256 bits) [cpu] driver lavapipe (llvmpipe), Mesa 22.3.6
// (LLVM 15.0.6)", and why the device is unusable, if it is.
std::string device_line(const device_info& d);

// Three lines per device (name, type, Vulkan version; driver; ray tracing), the chosen one
// marked with '*'.
std::string describe_devices(const std::vector<device_info>& devices, std::size_t chosen);

}  // namespace rtvk::gpu
