#include "instance.h"

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "pin_drivers.h"
#include "vk_error.h"

namespace rtvk::gpu {
namespace {

constexpr const char* validation_layer = "VK_LAYER_KHRONOS_validation";

void load_vulkan() {
  static const VkResult loaded = volkInitialize();
  if (loaded != VK_SUCCESS) throw no_device_error("no Vulkan loader (libvulkan.so.1) found");
}

VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                          VkDebugUtilsMessageTypeFlagsEXT,
                                          const VkDebugUtilsMessengerCallbackDataEXT* data,
                                          void* user) {
  // The loader reports through the same messenger (e.g. "Driver ... ignored" when a driver is
  // selected by VK_DRIVER_FILES): those are not validation findings.
  const bool from_loader =
      data->pMessageIdName && std::strcmp(data->pMessageIdName, "Loader Message") == 0;
  if (from_loader) {
    if (severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT)
      std::fprintf(stderr, "loader: %s\n", data->pMessage);
    return VK_FALSE;
  }
  std::fprintf(stderr, "validation: %s\n", data->pMessage);
  static_cast<std::atomic<std::uint32_t>*>(user)->fetch_add(1);
  return VK_FALSE;
}

bool has_layer(const char* name) {
  std::uint32_t n = 0;
  vk_check(vkEnumerateInstanceLayerProperties(&n, nullptr), "vkEnumerateInstanceLayerProperties");
  std::vector<VkLayerProperties> layers(n);
  vk_check(vkEnumerateInstanceLayerProperties(&n, layers.data()),
           "vkEnumerateInstanceLayerProperties");
  for (const auto& l : layers)
    if (std::strcmp(l.layerName, name) == 0) return true;
  return false;
}

bool has_extension(const char* name) {
  std::uint32_t n = 0;
  vk_check(vkEnumerateInstanceExtensionProperties(nullptr, &n, nullptr),
           "vkEnumerateInstanceExtensionProperties");
  std::vector<VkExtensionProperties> exts(n);
  vk_check(vkEnumerateInstanceExtensionProperties(nullptr, &n, exts.data()),
           "vkEnumerateInstanceExtensionProperties");
  for (const auto& e : exts)
    if (std::strcmp(e.extensionName, name) == 0) return true;
  return false;
}

}  // namespace

vulkan_instance::vulkan_instance(bool validate) : validating_(validate) {
  load_vulkan();
  if (volkGetInstanceVersion() < VK_API_VERSION_1_1)
    throw no_device_error("the Vulkan loader supports only Vulkan 1.0; rtvk needs 1.1");

  std::vector<const char*> layers, extensions;
  VkInstanceCreateFlags flags = 0;
  // Portability drivers (MoltenVK and the like) are listed only when asked for.
  if (has_extension(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME)) {
    extensions.push_back(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME);
    flags |= VK_INSTANCE_CREATE_ENUMERATE_PORTABILITY_BIT_KHR;
  }
  if (validate) {
    if (!has_layer(validation_layer))
      throw std::runtime_error(std::string("validation was requested but ") + validation_layer +
                               " is not installed (apt-get install vulkan-validationlayers)");
    layers.push_back(validation_layer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  }

  VkDebugUtilsMessengerCreateInfoEXT messenger_info{
      VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messenger_info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                   VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messenger_info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messenger_info.pfnUserCallback = on_message;
  messenger_info.pUserData = &messages_;

  // Synchronization validation too: a missing barrier is as much a bug as a bad parameter.
  const VkValidationFeatureEnableEXT enables[] = {
      VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  features.pNext = &messenger_info;
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = enables;

  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "rtvk";
  app.pEngineName = "rtvk";
  app.apiVersion = VK_API_VERSION_1_1;
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pNext = validate ? &features : nullptr;  // the messenger also covers instance creation
  info.flags = flags;
  info.pApplicationInfo = &app;
  info.enabledLayerCount = std::uint32_t(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = std::uint32_t(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();

  VkInstance instance = VK_NULL_HANDLE;
  const VkResult r = vkCreateInstance(&info, nullptr, &instance);
  if (r == VK_ERROR_INCOMPATIBLE_DRIVER)
    throw no_device_error("vkCreateInstance: VK_ERROR_INCOMPATIBLE_DRIVER (no Vulkan driver)");
  vk_check(r, "vkCreateInstance");
  instance_ = unique_instance(instance);
  volkLoadInstance(instance);
  pin_driver_libraries();

  if (validate) {
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
    vk_check(vkCreateDebugUtilsMessengerEXT(instance, &messenger_info, nullptr, &messenger),
             "vkCreateDebugUtilsMessengerEXT");
    messenger_ = unique_messenger(instance, messenger);
  }
}

}  // namespace rtvk::gpu
