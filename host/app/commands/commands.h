#pragma once
#include <CLI/CLI.hpp>
#include <functional>

namespace rtvk {

// Each subcommand registers its options on `app` and returns the function that runs it once
// parsing succeeded; that function returns the exit status or throws.
using command_action = std::function<int()>;

command_action add_render_command(CLI::App& app);
command_action add_compare_command(CLI::App& app);
command_action add_devices_command(CLI::App& app);
command_action add_scene_command(CLI::App& app);
command_action add_bench_command(CLI::App& app);
command_action add_merge_command(CLI::App& app);
command_action add_view_command(CLI::App& app);

}  // namespace rtvk
