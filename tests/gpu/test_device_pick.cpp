// The suite's device pick (tests/software_device.h): lavapipe is found by what its driver
// reports, whatever its manifest is called, and a loader without it gets a message saying what
// was looked for and what was offered.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "ci.h"
#include "errors.h"
#include "fault_layer.h"
#include "process.h"
#include "software_device.h"
#include "temp_dir.h"
#include "vk_error.h"

namespace rtvk {
namespace {

namespace fs = std::filesystem;

std::string this_executable() {
  return fs::read_symlink("/proc/self/exe").string();
}

// `rtvk_tests --pick-software-device` with the loader's environment changed by `env`.
test::process_result run_pick(const std::vector<std::string>& env) {
  return test::running_rtvk({"--pick-software-device"}, env, "", this_executable()).wait();
}

std::vector<std::string> split(const std::string& list) {
  std::vector<std::string> out;
  std::stringstream in(list);
  for (std::string item; std::getline(in, item, ':');)
    if (!item.empty()) out.push_back(item);
  return out;
}

std::string env_or(const char* name, const std::string& fallback) {
  const char* v = std::getenv(name);
  return v && *v ? v : fallback;
}

// The driver manifests the loader reads in this environment: the files or folders of
// VK_DRIVER_FILES (or the older VK_ICD_FILENAMES) when set, else its search folders; and those
// of VK_ADD_DRIVER_FILES.
std::vector<fs::path> loader_manifests() {
  std::vector<std::string> places =
      split(env_or("VK_DRIVER_FILES", env_or("VK_ICD_FILENAMES", "")));
  if (places.empty()) {
    const std::string home = env_or("HOME", "/root");
    std::vector<std::string> roots{env_or("XDG_CONFIG_HOME", home + "/.config")};
    for (const auto& d : split(env_or("XDG_CONFIG_DIRS", "/etc/xdg"))) roots.push_back(d);
    roots.push_back("/etc");
    roots.push_back(env_or("XDG_DATA_HOME", home + "/.local/share"));
    for (const auto& d : split(env_or("XDG_DATA_DIRS", "/usr/local/share:/usr/share")))
      roots.push_back(d);
    for (const auto& r : roots) places.push_back(r + "/vulkan/icd.d");
  }
  for (const auto& p : split(env_or("VK_ADD_DRIVER_FILES", ""))) places.push_back(p);
  std::vector<fs::path> manifests;
  for (const auto& place : places) {
    std::error_code ec;
    if (fs::is_directory(place, ec)) {
      for (const auto& e : fs::directory_iterator(place, ec))
        if (e.path().extension() == ".json") manifests.push_back(e.path());
    } else if (fs::is_regular_file(place, ec)) {
      manifests.push_back(place);
    }
  }
  return manifests;
}

// A copy of `manifest` in `folder` under a new name, its library path made absolute where it
// was relative to the manifest's folder (a bare file name stays: the dynamic linker finds it).
// Empty when the file is not a driver manifest.
fs::path renamed_copy(const fs::path& manifest, const fs::path& folder, int n) {
  nlohmann::json j;
  try {
    std::ifstream in(manifest);
    j = nlohmann::json::parse(in);
  } catch (const std::exception&) {
    return {};
  }
  if (!j.contains("ICD") || !j["ICD"].contains("library_path")) return {};
  const std::string lib = j["ICD"]["library_path"];
  if (lib.find('/') != std::string::npos && fs::path(lib).is_relative())
    j["ICD"]["library_path"] = (manifest.parent_path() / lib).lexically_normal().string();
  const fs::path copy = folder / ("renamed-driver-" + std::to_string(n) + ".json");
  std::ofstream(copy) << j.dump(2);
  return copy;
}

TEST(DevicePick, FindsLavapipeUnderAManifestOfAnotherName) {
  const test::device_pick& here = test::software_device();
  if (!here.found || here.description.find("lavapipe") == std::string::npos) {
    if (test::in_ci()) FAIL() << "CI must offer lavapipe: " << here.failure << here.description;
    GTEST_SKIP() << "lavapipe is not on offer here: " << here.failure << here.description;
  }
  const test::temp_dir dir;
  int n = 0, lavapipes = 0;
  std::string tried;
  for (const fs::path& m : loader_manifests()) {
    const fs::path copy = renamed_copy(m, dir.path(), n++);
    if (copy.empty()) continue;
    // The loader sees this one driver, by its new name, and nothing else.
    const auto r = run_pick({"VK_DRIVER_FILES=" + copy.string(),
                             "VK_ICD_FILENAMES=" + copy.string(), "VK_ADD_DRIVER_FILES"});
    tried += m.string() + " as " + copy.filename().string() + ": " +
             (r.status == 0 ? r.out : r.err) + "\n";
    if (r.status == 0 && r.out.find("lavapipe") != std::string::npos) ++lavapipes;
  }
  EXPECT_GE(lavapipes, 1) << "no renamed manifest gave lavapipe:\n" << tried;
}

TEST(DevicePick, WithoutASoftwareDeviceItSaysWhatItLookedForAndWhatTheLoaderOffered) {
  const auto none = run_pick({"VK_DRIVER_FILES=/nonexistent/icd.json",
                              "VK_ICD_FILENAMES=/nonexistent/icd.json", "VK_ADD_DRIVER_FILES"});
  EXPECT_EQ(none.status, 1) << none.out;
  EXPECT_NE(none.err.find("VK_DRIVER_ID_MESA_LLVMPIPE"), std::string::npos) << none.err;
  EXPECT_NE(none.err.find("offered no device"), std::string::npos) << none.err;
  EXPECT_NE(none.err.find("VK_DRIVER_FILES=/nonexistent/icd.json"), std::string::npos) << none.err;

  // A loader that offers a device, but no software one: the test layer dresses every device up
  // as an NVIDIA GPU.
  if (!test::software_device().found) {
    if (test::in_ci()) FAIL() << "CI must offer lavapipe: " << test::software_device().failure;
    GTEST_SKIP() << test::software_device().failure;
  }
  const auto disguised = run_pick(test::fault_environment("disguise-device"));
  EXPECT_EQ(disguised.status, 1) << disguised.out;
  EXPECT_NE(disguised.err.find("looked for a Vulkan device whose driver ID is "
                               "VK_DRIVER_ID_MESA_LLVMPIPE (lavapipe) or whose type is CPU"),
            std::string::npos)
      << disguised.err;
  EXPECT_NE(disguised.err.find("the loader offered 0: rtvk disguised GPU [discrete] driver "
                               "NVIDIA, 555.42.02"),
            std::string::npos)
      << disguised.err;
}

gpu::device_info device(std::uint32_t index, VkPhysicalDeviceType type, VkDriverId id,
                        const std::string& name) {
  gpu::device_info d;
  d.index = index;
  d.type = type;
  d.driver_id = id;
  d.name = name;
  return d;
}

TEST(DevicePick, PrefersLavapipeByDriverIdThenAnyCpuDevice) {
  const auto gpu = device(0, VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, VK_DRIVER_ID_MESA_RADV, "AMD");
  const auto swiftshader =
      device(1, VK_PHYSICAL_DEVICE_TYPE_CPU, VK_DRIVER_ID_GOOGLE_SWIFTSHADER, "SwiftShader");
  // lavapipe as a layer might present it: the type says nothing, the driver ID does.
  const auto lavapipe =
      device(2, VK_PHYSICAL_DEVICE_TYPE_OTHER, VK_DRIVER_ID_MESA_LLVMPIPE, "renamed");
  EXPECT_EQ(test::pick_software_device({gpu, swiftshader, lavapipe}).index, 2u);
  EXPECT_EQ(test::pick_software_device({gpu, swiftshader}).index, 1u);
  auto broken = lavapipe;
  broken.unusable_reason = "has no compute queue";
  EXPECT_EQ(test::pick_software_device({gpu, broken, swiftshader}).index, 1u);
  const auto none = test::pick_software_device({gpu}, "a note");
  EXPECT_FALSE(none.found);
  EXPECT_NE(none.failure.find("0: AMD [discrete] driver radv"), std::string::npos) << none.failure;
  EXPECT_NE(none.failure.find("(a note)"), std::string::npos) << none.failure;
}

// --device and RTVK_DEVICE against a machine of three devices, as their drivers describe them.
TEST(DeviceSelector, MatchesTheDevicesNameOrItsDriversNameCommonNameOrVersion) {
  auto radv = device(0, VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, VK_DRIVER_ID_MESA_RADV,
                     "AMD Radeon RX 6800 (RADV NAVI21)");
  radv.driver_name = "radv";
  radv.driver_info = "Mesa 24.0.1";
  auto lavapipe = device(1, VK_PHYSICAL_DEVICE_TYPE_CPU, VK_DRIVER_ID_MESA_LLVMPIPE,
                         "llvmpipe (LLVM 15.0.6, 256 bits)");
  lavapipe.driver_name = "llvmpipe";
  lavapipe.driver_info = "Mesa 25.0.7 (LLVM 15.0.6)";
  auto nvidia = device(2, VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, VK_DRIVER_ID_NVIDIA_PROPRIETARY,
                       "NVIDIA GeForce RTX 4090");
  nvidia.driver_name = "NVIDIA";
  nvidia.driver_info = "550.54.14";
  const std::vector<gpu::device_info> devices{radv, lavapipe, nvidia};
  const auto pick = [&](const std::string& s) { return gpu::select_device(devices, s); };
  EXPECT_EQ(pick(""), 0u);  // the default: the first discrete GPU
  EXPECT_EQ(pick("2"), 2u);
  EXPECT_EQ(pick("rtx 4090"), 2u);
  EXPECT_EQ(pick("Lavapipe"), 1u);  // the driver ID's common name, in no reported name
  EXPECT_EQ(pick("llvmpipe"), 1u);
  EXPECT_EQ(pick("Mesa 25"), 1u);  // the driver's version
  EXPECT_EQ(pick("mesa"), 0u);     // the first that matches
  EXPECT_EQ(pick("nvidia"), 2u);
  EXPECT_EQ(pick("550.54"), 2u);
  EXPECT_EQ(pick("radv"), 0u);
  // A device that cannot render is passed over for a later one that matches too.
  auto broken = devices;
  broken[0].unusable_reason = "has no compute queue";
  EXPECT_EQ(gpu::select_device(broken, "mesa"), 1u);
  try {
    gpu::select_device(broken, "radv", "RTVK_DEVICE");
    ADD_FAILURE() << "an unusable device was selected";
  } catch (const usage_error& e) {
    EXPECT_NE(std::string(e.what()).find("RTVK_DEVICE: 'radv' is AMD Radeon RX 6800 (RADV NAVI21), "
                                         "which has no compute queue"),
              std::string::npos)
        << e.what();
  }
  try {
    gpu::select_device(devices, "intel", "RTVK_DEVICE");
    ADD_FAILURE() << "'intel' matched a device";
  } catch (const usage_error& e) {
    EXPECT_NE(std::string(e.what()).find("RTVK_DEVICE: 'intel' matches no Vulkan device (devices: "
                                         "0: AMD Radeon RX 6800 (RADV NAVI21) [discrete] driver "
                                         "radv, Mesa 24.0.1; 1: llvmpipe"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(gpu::select_device({}, "lavapipe"), gpu::no_device_error);
}

// The family rtvk computes on: a compute-only one (asynchronous compute on AMD and NVIDIA, where
// rendering does not hold up the desktop's drawing) over the graphics family, which is still
// taken when there is nothing else; none without compute.
TEST(DevicePick, ComputeGoesToADedicatedComputeFamilyWhereThereIsOne) {
  const auto family = [](VkQueueFlags flags, std::uint32_t count = 1) {
    VkQueueFamilyProperties f{};
    f.queueFlags = flags;
    f.queueCount = count;
    return f;
  };
  const VkQueueFlags all = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT | VK_QUEUE_TRANSFER_BIT;
  const VkQueueFlags compute = VK_QUEUE_COMPUTE_BIT | VK_QUEUE_TRANSFER_BIT;
  // NVIDIA's and AMD's layouts: graphics first, then compute, then transfer.
  EXPECT_EQ(gpu::compute_family({family(all), family(compute), family(VK_QUEUE_TRANSFER_BIT)}), 1u);
  EXPECT_EQ(gpu::compute_family({family(all)}), 0u);  // lavapipe, most integrated GPUs
  EXPECT_EQ(gpu::compute_family({family(all), family(compute, 0)}), 0u);  // no queues in it
  EXPECT_EQ(gpu::compute_family({family(VK_QUEUE_TRANSFER_BIT)}), gpu::no_queue_family);
}

}  // namespace
}  // namespace rtvk
