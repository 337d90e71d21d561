#pragma once
#include <CLI/CLI.hpp>
#include <string>

#include "context.h"

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
  gpu::gpu_options options() const;
};

// What --device means on the command line ("" without it: RTVK_DEVICE, or the default pick).
// Sets `source` to the flag or variable the selector came from.
std::string device_selector(const std::string& flag_value, std::string& source);

// The help text of --device, shared by every command that has it.
extern const char* const device_flag_help;

}  // namespace rtvk
