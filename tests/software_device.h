#pragma once
// How the suite finds the device its GPU tests run on when RTVK_TEST_DEVICE names none: Mesa's
// lavapipe, or another software rasterizer, known by what its driver reports (the driver ID,
// else the device type), never by the file name or place of its manifest.
#include <cstdint>
#include <string>
#include <vector>

#include "physical_device.h"

namespace rtvk::test {

struct device_pick {
  bool found = false;       // a software device is on offer
  std::uint32_t index = 0;  // its place in the loader's list: the --device selector
  std::string description;  // the device and its driver, as `rtvk devices` shows them
  std::string failure;      // when none: what was looked for and what the loader offered
};

// The first device whose driver ID is VK_DRIVER_ID_MESA_LLVMPIPE, else the first usable device
// of type CPU. `offered_note` says where the list came from (for the failure message).
device_pick pick_software_device(const std::vector<gpu::device_info>& devices,
                                 const std::string& offered_note = "");

// The pick among what the Vulkan loader offers this process now (an instance with no layers).
device_pick find_software_device();

// find_software_device's result, computed once per process (when first asked for).
const device_pick& software_device();

// RTVK_TEST_DEVICE: a --device selector for a real device; empty means the software device.
std::string test_device();

// The --device selector of the device under test: RTVK_TEST_DEVICE, else the software device's
// index ("" when the suite found none).
std::string device_under_test();

// What every rtvk the tests start gets, so that it renders on the device under test:
// "RTVK_DEVICE=<selector>", or a bare "RTVK_DEVICE" (removed) when there is none.
std::string device_environment();

}  // namespace rtvk::test
