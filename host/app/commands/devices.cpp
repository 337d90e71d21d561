#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "commands.h"
#include "gpu_flags.h"
#include "instance.h"
#include "physical_device.h"
#include "vk_error.h"

namespace rtvk {
namespace {

struct devices_options {
  std::string device;     // mark this selection instead of the default pick
  bool validate = false;  // load the validation layer while listing
  bool json = false;      // one JSON array instead of text, for scripts
};

// What scripts pick a device by: what the driver reports, never a file name.
nlohmann::ordered_json to_json(const gpu::device_info& d, bool chosen) {
  return {{"index", d.index},
          {"name", d.name},
          {"type", gpu::type_name(d.type)},
          {"vendor_id", d.vendor_id},
          {"driver_id", int(d.driver_id)},
          {"driver", gpu::driver_common_name(d.driver_id)},
          {"driver_name", d.driver_name},
          {"driver_info", d.driver_info},
          {"driver_version", gpu::driver_version_string(d)},
          {"vulkan", gpu::version_string(d.api_version)},
          {"subgroup_size", d.subgroup_size},
          {"ray_queries", d.ray_queries},
          {"ray_tracing_pipelines", d.ray_tracing_pipelines},
          {"acceleration_structures", d.acceleration_structures},
          {"usable", d.unusable_reason.empty()},
          {"unusable_reason", d.unusable_reason},
          {"chosen", chosen}};
}

void print_devices(const devices_options& o, const std::vector<gpu::device_info>& devices,
                   std::size_t chosen, const std::string& selector, const std::string& source);

int show_devices(const devices_options& o) {
  const gpu::vulkan_instance instance(o.validate);
  const auto devices = gpu::list_devices(instance.get());
  if (devices.empty()) throw gpu::no_device_error("no Vulkan device found");
  std::string source;
  const std::string selector = device_selector(o.device, source);
  std::size_t chosen = devices.size();  // none: every device is listed, with why it cannot render
  try {
    chosen = gpu::select_device(devices, selector, source);
  } catch (const std::exception&) {  // no usable device, or the selected one is not
    print_devices(o, devices, chosen, selector, source);
    throw;
  }
  print_devices(o, devices, chosen, selector, source);
  return 0;
}

void print_devices(const devices_options& o, const std::vector<gpu::device_info>& devices,
                   std::size_t chosen, const std::string& selector, const std::string& source) {
  if (o.json) {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (const auto& d : devices) out.push_back(to_json(d, d.index == chosen));
    std::printf("%s\n", out.dump(2).c_str());
    return;
  }
  std::fputs(gpu::describe_devices(devices, chosen).c_str(), stdout);
  if (chosen < devices.size())
    std::printf("(* = the device rtvk renders on%s)\n",
                selector.empty() ? " by default" : (" with " + source + " " + selector).c_str());
}

// No loader, no driver or no device: no_device_error (exit 1), after an empty JSON array when
// JSON was asked for, so that scripts parse "none" too.
int run_devices(const devices_options& o) {
  try {
    return show_devices(o);
  } catch (const gpu::no_device_error&) {
    if (o.json) std::printf("[]\n");
    throw;
  }
}

}  // namespace

command_action add_devices_command(CLI::App& app) {
  auto opts = std::make_shared<devices_options>();
  CLI::App* cmd = app.add_subcommand(
      "devices", "List Vulkan devices, their drivers and ray tracing, and mark the one rtvk picks");
  cmd->add_option("--device", opts->device, std::string("Mark this device. ") + device_flag_help);
  cmd->add_flag("--validate", opts->validate, "Enable VK_LAYER_KHRONOS_validation");
  cmd->add_flag("--json", opts->json,
                "Print a JSON array, one object a device (index, name, type, driver_id, driver, "
                "driver_name, driver_info, vulkan, ray_queries, ray_tracing_pipelines, chosen, "
                "...)");
  return [opts] { return run_devices(*opts); };
}

}  // namespace rtvk
