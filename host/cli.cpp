#include "cli.h"

#include <exception>
#include <iostream>
#include <stdexcept>

#include "commands.h"
#include "errors.h"
#include "version.h"

namespace rtvk {

int run_cli(int argc, char** argv) {
  CLI::App app{"rtvk: a ray tracer with a CPU reference renderer and a Vulkan compute port",
               "rtvk"};
  app.set_version_flag("--version", std::string("rtvk ") + version_string);
  app.require_subcommand(1);

  const command_action render = add_render_command(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "rtvk: " << e.what() << " (see rtvk --help)\n";
    return 2;
  }

  try {
    if (app.got_subcommand("render")) return render();
    return 2;
  } catch (const usage_error& e) {
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
