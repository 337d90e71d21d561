#pragma once
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "context.h"
#include "engine_options.h"

namespace rtvk {

// The flags of every command that runs on a Vulkan device (render, bench, view), and the
// device options they make.
struct gpu_flags {
  std::string device;        // Vulkan device: an index or part of its name or its driver's
                             // ("" RTVK_DEVICE, else the default pick)
  bool validate = false;     // the Vulkan validation layer on (also RTVK_VALIDATE=1)
  double gpu_timeout = 120;  // seconds one GPU submission may take before it counts as hung

  // --device, --validate and --gpu-timeout.
  void add_to(CLI::App& cmd);
  // `ray_tracing`: enable what the device has of hardware ray tracing (wants_ray_tracing).
  gpu::gpu_options options(bool ray_tracing = false) const;
};

// --accel's words for the commands that render: bvh, none, rt-query, rt-pipeline, auto.
extern const char* const accel_flag_help;
const std::vector<std::string>& accel_words();
// Whether --accel asks for the device's ray tracing (rt-query, rt-pipeline, auto).
bool wants_ray_tracing(const std::string& accel);
// The GPU traversal --accel means on the context's device: auto takes ray queries where the
// device has them, else ray-tracing pipelines, else the compute BVH; rt-query and rt-pipeline
// on a device without them are refused (usage_error naming the missing extension).
gpu_traversal traversal_for(const std::string& accel, const gpu::gpu_context& ctx);

// What --device means on the command line ("" without it: RTVK_DEVICE, or the default pick).
// Sets `source` to the flag or variable the selector came from.
std::string device_selector(const std::string& flag_value, std::string& source);

// The help text of --device, shared by every command that has it.
extern const char* const device_flag_help;

}  // namespace rtvk
