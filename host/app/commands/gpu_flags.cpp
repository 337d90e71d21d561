#include "gpu_flags.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>

#include "errors.h"

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
  cmd.add_option(
         "--gpu-timeout", gpu_timeout,
         "Seconds one GPU submission may take before the device counts as hung (on lavapipe, "
         "a process's first submission to run each shader also gets 30 minutes to compile "
         "it)")
      ->check(CLI::Range(0.001, 86400.0))
      ->capture_default_str();
}

gpu::gpu_options gpu_flags::options(bool ray_tracing) const {
  gpu::gpu_options g;
  g.ray_tracing = ray_tracing;
  g.device = device_selector(device, g.device_source);
  const char* env = std::getenv("RTVK_VALIDATE");
  g.validate = validate || (env && std::string(env) == "1");
  g.fence_timeout =
      std::chrono::milliseconds(std::max<long long>(1, std::llround(gpu_timeout * 1000)));
  return g;
}

const char* const accel_flag_help =
    "How rays find their hits: bvh (rtvk's own BVH, the same on every device), none (every "
    "object tested; same image, slower), rt-query or rt-pipeline (the device's hardware ray "
    "tracing: VK_KHR_ray_query, VK_KHR_ray_tracing_pipeline; the GPU only), auto (the best the "
    "device offers, else bvh)";

const std::vector<std::string>& accel_words() {
  static const std::vector<std::string> words = {"bvh", "none", "rt-query", "rt-pipeline", "auto"};
  return words;
}

bool wants_ray_tracing(const std::string& accel) {
  return accel == "rt-query" || accel == "rt-pipeline" || accel == "auto";
}

gpu_traversal traversal_for(const std::string& accel, const gpu::gpu_context& ctx) {
  const gpu::device_info& d = ctx.device();
  if (accel == "auto")
    return ctx.ray_queries()             ? gpu_traversal::ray_query
           : ctx.ray_tracing_pipelines() ? gpu_traversal::ray_pipeline
                                         : gpu_traversal::compute;
  const bool pipelines = accel == "rt-pipeline";
  if (!pipelines && accel != "rt-query") return gpu_traversal::compute;
  if (pipelines ? ctx.ray_tracing_pipelines() : ctx.ray_queries())
    return pipelines ? gpu_traversal::ray_pipeline : gpu_traversal::ray_query;
  const std::string missing = gpu::missing_ray_tracing(d, pipelines);
  throw usage_error("--accel " + accel + ": device '" + d.name + "' (" + gpu::driver_string(d) +
                    ") lacks " + (missing.empty() ? std::string("it") : missing) +
                    "; --accel bvh or auto render on it");
}

}  // namespace rtvk
