#include <cstdio>
#include <memory>
#include <string>

#include "commands.h"
#include "instance.h"
#include "physical_device.h"
#include "vk_error.h"

namespace rtvk {
namespace {

struct devices_options {
  std::string device;     // mark this selection instead of the default pick
  bool validate = false;  // load the validation layer while listing
};

int run_devices(const devices_options& o) {
  const gpu::vulkan_instance instance(o.validate);
  const auto devices = gpu::list_devices(instance.get());
  if (devices.empty()) throw gpu::no_device_error("no Vulkan device found");
  const std::size_t chosen = gpu::select_device(devices, o.device);
  std::fputs(gpu::describe_devices(devices, chosen).c_str(), stdout);
  std::printf("(* = the device rtvk renders on%s)\n", o.device.empty() ? " by default" : "");
  return 0;
}

}  // namespace

command_action add_devices_command(CLI::App& app) {
  auto opts = std::make_shared<devices_options>();
  CLI::App* cmd = app.add_subcommand("devices", "List Vulkan devices and mark the one rtvk picks");
  cmd->add_option("--device", opts->device, "Mark this device: an index or part of its name");
  cmd->add_flag("--validate", opts->validate, "Enable VK_LAYER_KHRONOS_validation");
  return [opts] { return run_devices(*opts); };
}

}  // namespace rtvk
