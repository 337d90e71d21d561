#include "cli.h"

#include <csignal>
#include <exception>
#include <iostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "commands.h"
#include "errors.h"
#include "image_io.h"
#include "interrupt.h"
#include "version.h"

namespace rtvk {

int run_cli(int argc, char** argv) {
  CLI::App app{"rtvk: a ray tracer with a CPU reference renderer and a Vulkan compute port",
               "rtvk"};
  app.set_version_flag("--version", std::string("rtvk ") + version_string);
  app.require_subcommand(1);

  const std::vector<std::pair<std::string, command_action>> commands = {
      {"render", add_render_command(app)},   {"compare", add_compare_command(app)},
      {"devices", add_devices_command(app)}, {"scene", add_scene_command(app)},
      {"bench", add_bench_command(app)},     {"merge", add_merge_command(app)},
      {"view", add_view_command(app)},
  };

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "rtvk: " << e.what() << " (see rtvk --help)\n";
    return 2;
  }

  try {
    for (const auto& [name, action] : commands)
      if (app.got_subcommand(name)) return action();
    return 2;
  } catch (const usage_error& e) {
    std::cerr << "rtvk: " << e.what() << '\n';
    return 2;
  } catch (const render_cancelled& e) {
    const int sig = pending_signal();
    std::cerr << "rtvk: interrupted by " << (sig == SIGTERM ? "SIGTERM" : "SIGINT") << ": "
              << e.what() << "; the image being rendered was not written\n";
    return 128 + (sig ? sig : SIGINT);
  } catch (const image_read_error& e) {
    std::cerr << "rtvk: " << e.what() << '\n';
    return 2;
  } catch (const std::invalid_argument& e) {
    std::cerr << "rtvk: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "rtvk: error: " << e.what() << '\n';
    return 1;
  } catch (...) {
    std::cerr << "rtvk: error: unknown exception\n";
    return 1;
  }
}

}  // namespace rtvk
