#include "physical_device.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstring>

#include "errors.h"
#include "vk_error.h"

namespace rtvk::gpu {
namespace {

std::vector<VkExtensionProperties> device_extensions(VkPhysicalDevice dev) {
  std::uint32_t n = 0;
  vk_check(vkEnumerateDeviceExtensionProperties(dev, nullptr, &n, nullptr),
           "vkEnumerateDeviceExtensionProperties");
  std::vector<VkExtensionProperties> exts(n);
  vk_check(vkEnumerateDeviceExtensionProperties(dev, nullptr, &n, exts.data()),
           "vkEnumerateDeviceExtensionProperties");
  exts.resize(n);
  return exts;
}

bool has(const std::vector<VkExtensionProperties>& exts, const char* name) {
  return std::any_of(exts.begin(), exts.end(),
                     [&](const auto& e) { return std::strcmp(e.extensionName, name) == 0; });
}

// What the device offers of hardware ray tracing: the extension must be listed and its feature
// reported, since a driver may list an extension whose feature is off.
void describe_ray_tracing(VkPhysicalDevice dev, const std::vector<VkExtensionProperties>& exts,
                          device_info& d) {
  if (d.api_version < VK_API_VERSION_1_1) return;
  if (!has(exts, VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME)) return;
  VkPhysicalDeviceAccelerationStructureFeaturesKHR as{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
  VkPhysicalDeviceRayQueryFeaturesKHR rq{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR};
  VkPhysicalDeviceRayTracingPipelineFeaturesKHR rt{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR};
  VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  features.pNext = &as;
  void** next = &as.pNext;  // only structures of listed extensions go on the chain
  if (has(exts, VK_KHR_RAY_QUERY_EXTENSION_NAME)) {
    *next = &rq;
    next = &rq.pNext;
  }
  if (has(exts, VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME)) *next = &rt;
  vkGetPhysicalDeviceFeatures2(dev, &features);
  d.acceleration_structures = as.accelerationStructure == VK_TRUE;
  d.ray_queries = d.acceleration_structures && rq.rayQuery == VK_TRUE;
  d.ray_tracing_pipelines = d.acceleration_structures && rt.rayTracingPipeline == VK_TRUE;
}

device_info describe_queues(VkPhysicalDevice dev, const VkPhysicalDeviceProperties& props,
                            device_info& d);

device_info describe(VkPhysicalDevice dev, std::uint32_t index) {
  VkPhysicalDeviceProperties props{};
  vkGetPhysicalDeviceProperties(dev, &props);
  device_info d;
  d.index = index;
  d.handle = dev;
  d.name = props.deviceName;
  d.type = props.deviceType;
  d.vendor_id = props.vendorID;
  d.driver_version = props.driverVersion;
  d.api_version = props.apiVersion;
  d.limits = props.limits;

  std::memcpy(d.pipeline_cache_uuid, props.pipelineCacheUUID, VK_UUID_SIZE);
  d.device_id = props.deviceID;
  // Vulkan 1.1's queries only on a 1.1 device: on a 1.0 one, vkGetPhysicalDeviceProperties2 is
  // not the device's to answer (the device is listed, as unusable, below).
  if (props.apiVersion < VK_API_VERSION_1_1) return describe_queues(dev, props, d);
  VkPhysicalDeviceIDProperties ids{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ID_PROPERTIES};
  VkPhysicalDeviceMaintenance3Properties maintenance3{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES, &ids};
  VkPhysicalDeviceSubgroupProperties subgroup{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES,
                                              &maintenance3};
  VkPhysicalDeviceProperties2 with_subgroup{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  with_subgroup.pNext = &subgroup;
  vkGetPhysicalDeviceProperties2(dev, &with_subgroup);
  d.subgroup_size = std::max(1u, subgroup.subgroupSize);
  d.max_allocation_size = maintenance3.maxMemoryAllocationSize;
  std::memcpy(d.driver_uuid, ids.driverUUID, VK_UUID_SIZE);

  const auto exts = device_extensions(dev);
  if (props.apiVersion >= VK_API_VERSION_1_2 ||
      has(exts, VK_KHR_DRIVER_PROPERTIES_EXTENSION_NAME)) {
    VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceProperties2 props2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    props2.pNext = &driver;
    vkGetPhysicalDeviceProperties2(dev, &props2);
    d.driver_id = driver.driverID;
    d.driver_name = driver.driverName;
    d.driver_info = driver.driverInfo;
  }
  describe_ray_tracing(dev, exts, d);
  return describe_queues(dev, props, d);
}

// The compute queue family, or why the device cannot render.
device_info describe_queues(VkPhysicalDevice dev, const VkPhysicalDeviceProperties& props,
                            device_info& d) {
  std::uint32_t n = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(dev, &n, nullptr);
  d.queue_families.resize(n);
  vkGetPhysicalDeviceQueueFamilyProperties(dev, &n, d.queue_families.data());
  const std::uint32_t compute = compute_family(d.queue_families);
  if (props.apiVersion < VK_API_VERSION_1_1)
    d.unusable_reason = "supports only Vulkan " + version_string(props.apiVersion);
  else if (compute == no_queue_family)
    d.unusable_reason = "has no compute queue";
  else
    use_queue_family(d, compute);
  return d;
}

int type_rank(VkPhysicalDeviceType t) {
  switch (t) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return 3;
    default:
      return 4;
  }
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

bool contains(const std::string& text, const std::string& part) {
  return !text.empty() && lower(text).find(lower(part)) != std::string::npos;
}

bool matches(const device_info& d, const std::string& selector) {
  return contains(d.name, selector) || contains(d.driver_name, selector) ||
         contains(driver_common_name(d.driver_id), selector) || contains(d.driver_info, selector);
}

std::string yes_no(bool b) {
  return b ? "yes" : "no";
}

}  // namespace

std::uint32_t compute_family(const std::vector<VkQueueFamilyProperties>& families) {
  std::uint32_t first = no_queue_family;
  for (std::uint32_t k = 0; k < families.size(); ++k) {
    const VkQueueFlags f = families[k].queueFlags;
    if (!(f & VK_QUEUE_COMPUTE_BIT) || families[k].queueCount == 0) continue;
    if (!(f & VK_QUEUE_GRAPHICS_BIT)) return k;
    if (first == no_queue_family) first = k;
  }
  return first;
}

namespace {
// What each hardware path needs, in the order a message names the first one missing.
constexpr const char* accel_needs[] = {VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME,
                                       VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME,
                                       VK_KHR_BUFFER_DEVICE_ADDRESS_EXTENSION_NAME,
                                       VK_EXT_DESCRIPTOR_INDEXING_EXTENSION_NAME,
                                       VK_KHR_SPIRV_1_4_EXTENSION_NAME,
                                       VK_KHR_SHADER_FLOAT_CONTROLS_EXTENSION_NAME};
}  // namespace

std::vector<const char*> ray_tracing_extensions(const device_info& d) {
  const auto exts = device_extensions(d.handle);
  std::vector<const char*> out;
  for (const char* e : accel_needs)
    if (has(exts, e)) out.push_back(e);
  if (d.ray_queries) out.push_back(VK_KHR_RAY_QUERY_EXTENSION_NAME);
  if (d.ray_tracing_pipelines) out.push_back(VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME);
  return out;
}

std::string missing_ray_tracing(const device_info& d, bool pipelines) {
  const auto exts = device_extensions(d.handle);
  for (const char* e : accel_needs)
    if (!has(exts, e)) return e;
  const char* own =
      pipelines ? VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME : VK_KHR_RAY_QUERY_EXTENSION_NAME;
  if (!has(exts, own)) return own;
  if (!d.acceleration_structures) return "the accelerationStructure feature";
  if (pipelines ? !d.ray_tracing_pipelines : !d.ray_queries)
    return pipelines ? "the rayTracingPipeline feature" : "the rayQuery feature";
  return {};
}

bool has_device_extension(VkPhysicalDevice dev, const char* name) {
  return has(device_extensions(dev), name);
}

std::vector<device_info> list_devices(VkInstance instance) {
  std::uint32_t n = 0;
  vk_check(vkEnumeratePhysicalDevices(instance, &n, nullptr), "vkEnumeratePhysicalDevices");
  std::vector<VkPhysicalDevice> handles(n);
  vk_check(vkEnumeratePhysicalDevices(instance, &n, handles.data()), "vkEnumeratePhysicalDevices");
  std::vector<device_info> devices;
  for (std::uint32_t i = 0; i < n; ++i) devices.push_back(describe(handles[i], i));
  return devices;
}

std::string type_name(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return "discrete";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return "integrated";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return "virtual";
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return "cpu";
    default:
      return "other";
  }
}

std::string version_string(std::uint32_t v) {
  return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) +
         "." + std::to_string(VK_API_VERSION_PATCH(v));
}

std::string driver_version_string(const device_info& d) {
  const std::uint32_t v = d.driver_version;
  if (d.vendor_id == 0x10DE)  // NVIDIA: 10.8.8.6 bits
    return std::to_string(v >> 22) + "." + std::to_string((v >> 14) & 0xff) + "." +
           std::to_string((v >> 6) & 0xff) + "." + std::to_string(v & 0x3f);
  return version_string(v);
}

std::string driver_common_name(VkDriverId id) {
  switch (id) {
    case VK_DRIVER_ID_MESA_LLVMPIPE:
      return "lavapipe";
    case VK_DRIVER_ID_MESA_RADV:
      return "radv";
    case VK_DRIVER_ID_INTEL_OPEN_SOURCE_MESA:
      return "anv";
    case VK_DRIVER_ID_NVIDIA_PROPRIETARY:
      return "nvidia";
    case VK_DRIVER_ID_AMD_PROPRIETARY:
      return "amd proprietary";
    case VK_DRIVER_ID_AMD_OPEN_SOURCE:
      return "amdvlk";
    case VK_DRIVER_ID_INTEL_PROPRIETARY_WINDOWS:
      return "intel";
    case VK_DRIVER_ID_GOOGLE_SWIFTSHADER:
      return "swiftshader";
    case VK_DRIVER_ID_MOLTENVK:
      return "moltenvk";
    case VK_DRIVER_ID_MESA_TURNIP:
      return "turnip";
    case VK_DRIVER_ID_MESA_V3DV:
      return "v3dv";
    case VK_DRIVER_ID_MESA_PANVK:
      return "panvk";
    case VK_DRIVER_ID_MESA_VENUS:
      return "venus";
    case VK_DRIVER_ID_MESA_DOZEN:
      return "dozen";
    case VK_DRIVER_ID_MESA_NVK:
      return "nvk";
    default:
      return "";
  }
}

std::string driver_string(const device_info& d) {
  const std::string common = driver_common_name(d.driver_id);
  std::string name;
  if (d.driver_name.empty())
    name = common.empty() ? "?" : common;
  else if (common.empty() || lower(common) == lower(d.driver_name))
    name = d.driver_name;  // "NVIDIA", as the driver spells it
  else
    name = common + " (" + d.driver_name + ")";
  return name + ", " + (d.driver_info.empty() ? driver_version_string(d) : d.driver_info);
}

std::size_t default_device(const std::vector<device_info>& devices) {
  std::size_t best = devices.size();
  for (std::size_t i = 0; i < devices.size(); ++i) {
    if (!devices[i].unusable_reason.empty()) continue;
    if (best == devices.size() || type_rank(devices[i].type) < type_rank(devices[best].type))
      best = i;
  }
  if (best == devices.size()) {
    std::string found;
    for (const device_info& d : devices) found += "; " + d.name + " " + d.unusable_reason;
    throw no_device_error(devices.empty()
                              ? "no Vulkan device found"
                              : "no usable Vulkan device (need 1.1 with compute" + found + ")");
  }
  return best;
}

std::size_t select_device(const std::vector<device_info>& devices, const std::string& selector,
                          const std::string& source) {
  if (selector.empty() || devices.empty()) return default_device(devices);
  std::size_t found = devices.size();
  unsigned index = 0;
  const auto [end, ec] = std::from_chars(selector.data(), selector.data() + selector.size(), index);
  if (ec == std::errc() && end == selector.data() + selector.size()) {
    if (index < devices.size()) found = index;
  } else {
    // The first usable device that matches, else the first that matches (refused below).
    for (std::size_t i = 0; i < devices.size(); ++i) {
      if (!matches(devices[i], selector)) continue;
      if (found == devices.size()) found = i;
      if (devices[i].unusable_reason.empty()) {
        found = i;
        break;
      }
    }
  }
  std::string listing;
  for (const auto& d : devices) listing += (listing.empty() ? "" : "; ") + device_line(d);
  if (devices.empty()) listing = "none";
  if (found == devices.size())
    throw usage_error(source + ": '" + selector +
                      "' matches no Vulkan device (devices: " + listing + ")");
  if (!devices[found].unusable_reason.empty())
    throw usage_error(source + ": '" + selector + "' is " + devices[found].name + ", which " +
                      devices[found].unusable_reason);
  return found;
}

std::string device_line(const device_info& d) {
  return std::to_string(d.index) + ": " + d.name + " [" + type_name(d.type) + "] driver " +
         driver_string(d) +
         (d.unusable_reason.empty() ? "" : " (unusable: " + d.unusable_reason + ")");
}

std::string describe_devices(const std::vector<device_info>& devices, std::size_t chosen) {
  std::string out;
  for (const auto& d : devices) {
    out += (d.index == chosen ? "* " : "  ") + std::to_string(d.index) + ": " + d.name + " [" +
           type_name(d.type) + "] Vulkan " + version_string(d.api_version) + ", subgroup " +
           std::to_string(d.subgroup_size) +
           (d.unusable_reason.empty() ? "" : " -- unusable: " + d.unusable_reason) + "\n";
    out += "     driver " + driver_string(d) + "\n";
    out += "     ray queries: " + yes_no(d.ray_queries) +
           ", ray-tracing pipelines: " + yes_no(d.ray_tracing_pipelines) +
           ", acceleration structures: " + yes_no(d.acceleration_structures) + "\n";
  }
  return out;
}

void use_queue_family(device_info& d, std::uint32_t family) {
  d.compute_queue_family = family;
  d.timestamp_valid_bits = d.queue_families.at(family).timestampValidBits;
}

}  // namespace rtvk::gpu
