#include <cstdio>
#include <memory>
#include <string>

#include "commands.h"
#include "scene.h"
#include "scene_file.h"
#include "scene_flags.h"

namespace rtvk {

command_action add_scene_command(CLI::App& app) {
  auto name = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand("scene", "Built-in scenes and scene files");
  cmd->require_subcommand(1);
  CLI::App* dump = cmd->add_subcommand(
      "dump", "Write a scene (built-in name or .json file) as JSON to standard output");
  dump->add_option("NAME", *name, "Scene to write")->required();
  auto paths = std::make_shared<scene_path_flags>();
  paths->add_to(*dump);
  CLI::App* list = cmd->add_subcommand("list", "List the built-in scenes");
  return [name, dump, list, paths]() {
    if (dump->parsed()) {
      std::fputs(dump_scene_json(load_scene(*name, paths->access())).c_str(), stdout);
    } else if (list->parsed()) {
      for (const auto& n : scene_names()) std::printf("%s\n", n.c_str());
      std::printf("spheres:N (N from 1 to %u)\n", unsigned(max_scene_spheres));
    }
    return 0;
  };
}

}  // namespace rtvk
