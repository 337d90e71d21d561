#include "software_device.h"

#include <cstdlib>
#include <exception>

#include "instance.h"

namespace rtvk::test {
namespace {

constexpr const char* looked_for =
    "a Vulkan device whose driver ID is VK_DRIVER_ID_MESA_LLVMPIPE (lavapipe) or whose type is "
    "CPU";

// The loader's variables that change which drivers it reads, as set now.
std::string loader_variables() {
  std::string out;
  for (const char* name : {"VK_DRIVER_FILES", "VK_ICD_FILENAMES", "VK_ADD_DRIVER_FILES",
                           "VK_LOADER_DRIVERS_SELECT", "VK_LOADER_DRIVERS_DISABLE"}) {
    if (const char* v = std::getenv(name))
      out += std::string(out.empty() ? "" : ", ") + name + "=" + v;
  }
  return out.empty() ? "no loader variables set" : out;
}

}  // namespace

device_pick pick_software_device(const std::vector<gpu::device_info>& devices,
                                 const std::string& offered_note) {
  const gpu::device_info* chosen = nullptr;
  for (const auto& d : devices)
    if (!chosen && d.driver_id == VK_DRIVER_ID_MESA_LLVMPIPE && d.unusable_reason.empty())
      chosen = &d;
  for (const auto& d : devices)
    if (!chosen && d.type == VK_PHYSICAL_DEVICE_TYPE_CPU && d.unusable_reason.empty()) chosen = &d;
  device_pick pick;
  if (chosen) {
    pick.found = true;
    pick.index = chosen->index;
    pick.description = gpu::device_line(*chosen);
    return pick;
  }
  std::string offered;
  for (const auto& d : devices) offered += (offered.empty() ? "" : "; ") + gpu::device_line(d);
  pick.failure = std::string("looked for ") + looked_for + "; the loader offered " +
                 (offered.empty() ? "no device" : offered) +
                 (offered_note.empty() ? "" : " (" + offered_note + ")") +
                 ". Install mesa-vulkan-drivers, or name a device with RTVK_TEST_DEVICE";
  return pick;
}

device_pick find_software_device() {
  std::string note = loader_variables();
  try {
    const gpu::vulkan_instance instance(false);
    return pick_software_device(gpu::list_devices(instance.get()), note);
  } catch (const std::exception& e) {
    return pick_software_device({}, note + "; " + e.what());
  }
}

const device_pick& software_device() {
  static const device_pick pick = find_software_device();
  return pick;
}

std::string test_device() {
  const char* d = std::getenv("RTVK_TEST_DEVICE");
  return d ? d : "";
}

std::string device_under_test() {
  if (!test_device().empty()) return test_device();
  const device_pick& pick = software_device();
  return pick.found ? std::to_string(pick.index) : "";
}

std::string device_environment() {
  const std::string device = device_under_test();
  return device.empty() ? "RTVK_DEVICE" : "RTVK_DEVICE=" + device;
}

}  // namespace rtvk::test
