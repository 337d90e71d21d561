#include "gpu_flags.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>

namespace rtvk {

const char* const device_flag_help =
    "Vulkan device: an index, or part of its name or its driver's name or version, e.g. "
    "lavapipe, radv, nvidia, 'Mesa 25' (see rtvk devices; default RTVK_DEVICE, else the best "
    "device)";

std::string device_selector(const std::string& flag_value, std::string& source) {
  source = "--device";
  if (!flag_value.empty()) return flag_value;
  const char* env = std::getenv("RTVK_DEVICE");
  if (!env || !*env) return "";
  source = "RTVK_DEVICE";
  return env;
}

void gpu_flags::add_to(CLI::App& cmd) {
  cmd.add_option("--device", device, device_flag_help);
  cmd.add_flag("--validate", validate, "Enable VK_LAYER_KHRONOS_validation (also RTVK_VALIDATE=1)");
  cmd.add_option("--gpu-timeout", gpu_timeout,
                 "Seconds one GPU submission may take before the device counts as hung")
      ->check(CLI::Range(0.001, 86400.0))
      ->capture_default_str();
}

gpu::gpu_options gpu_flags::options() const {
  gpu::gpu_options g;
  g.device = device_selector(device, g.device_source);
  const char* env = std::getenv("RTVK_VALIDATE");
  g.validate = validate || (env && std::string(env) == "1");
  g.fence_timeout =
      std::chrono::milliseconds(std::max<long long>(1, std::llround(gpu_timeout * 1000)));
  return g;
}

}  // namespace rtvk
