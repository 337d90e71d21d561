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

// Loads the loader; throws no_device_error when it is missing or knows only Vulkan 1.0.
void require_vulkan_1_1() {
  load_vulkan();
  if (volkGetInstanceVersion() < VK_API_VERSION_1_1)
    throw no_device_error("the Vulkan loader supports only Vulkan 1.0; rtvk needs 1.1");
}

// What the instance is created with besides the application info.
struct instance_features {
  std::vector<const char*> layers;      // layer names to enable
  std::vector<const char*> extensions;  // instance extension names to enable
  VkInstanceCreateFlags flags = 0;      // VkInstanceCreateInfo::flags
};

instance_features choose_features(bool validate) {
  instance_features f;
  // Portability drivers (MoltenVK and the like) are listed only when asked for.
  if (has_extension(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME)) {
    f.extensions.push_back(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME);
    f.flags |= VK_INSTANCE_CREATE_ENUMERATE_PORTABILITY_BIT_KHR;
  }
  if (validate) {
    if (!has_layer(validation_layer))
      throw std::runtime_error(std::string("validation was requested but ") + validation_layer +
                               " is not installed (apt-get install vulkan-validationlayers)");
    f.layers.push_back(validation_layer);
    f.extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  }
  return f;
}

// Warnings and errors of every type go to on_message, which counts them in *counter.
VkDebugUtilsMessengerCreateInfoEXT messenger_info(std::atomic<std::uint32_t>* counter) {
  VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                         VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  info.pfnUserCallback = on_message;
  info.pUserData = counter;
  return info;
}

// `messenger` (validation only, else null) also covers instance creation itself.
VkInstance create_instance(const instance_features& f,
                           const VkDebugUtilsMessengerCreateInfoEXT* messenger) {
  // Synchronization validation too: a missing barrier is as much a bug as a bad parameter.
  const VkValidationFeatureEnableEXT enables[] = {
      VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  features.pNext = messenger;
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = enables;

  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "rtvk";
  app.pEngineName = "rtvk";
  app.apiVersion = VK_API_VERSION_1_1;
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pNext = messenger ? &features : nullptr;
  info.flags = f.flags;
  info.pApplicationInfo = &app;
  info.enabledLayerCount = std::uint32_t(f.layers.size());
  info.ppEnabledLayerNames = f.layers.data();
  info.enabledExtensionCount = std::uint32_t(f.extensions.size());
  info.ppEnabledExtensionNames = f.extensions.data();

  VkInstance instance = VK_NULL_HANDLE;
  const VkResult r = vkCreateInstance(&info, nullptr, &instance);
  if (r == VK_ERROR_INCOMPATIBLE_DRIVER)
    throw no_device_error("vkCreateInstance: VK_ERROR_INCOMPATIBLE_DRIVER (no Vulkan driver)");
  vk_check(r, "vkCreateInstance");
  return instance;
}

unique_messenger make_messenger(VkInstance instance,
                                const VkDebugUtilsMessengerCreateInfoEXT& info) {
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  vk_check(vkCreateDebugUtilsMessengerEXT(instance, &info, nullptr, &messenger),
           "vkCreateDebugUtilsMessengerEXT");
  return unique_messenger(instance, messenger);
}

}  // namespace

vulkan_instance::vulkan_instance(bool validate, const std::vector<std::string>& extensions)
    : validating_(validate) {
  require_vulkan_1_1();
  instance_features features = choose_features(validate);
  for (const std::string& e : extensions) {
    if (!has_extension(e.c_str()))
      throw std::runtime_error("the Vulkan loader has no " + e + " (needed to show a window)");
    features.extensions.push_back(e.c_str());
  }
  const VkDebugUtilsMessengerCreateInfoEXT messenger = messenger_info(&messages_);
  instance_ = unique_instance(create_instance(features, validate ? &messenger : nullptr));
  volkLoadInstance(instance_.get());
  pin_driver_libraries();
  if (validate) messenger_ = make_messenger(instance_.get(), messenger);
}

}  // namespace rtvk::gpu
