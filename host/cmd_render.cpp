#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "aspect.h"
#include "camera.h"
#include "commands.h"
#include "errors.h"
#include "format.h"
#include "image_io.h"
#include "quantize.h"
#include "render_cpu.h"
#include "scene.h"

namespace rtvk {
namespace {

struct render_options {
  std::string scene = "seed";     // built-in scene name
  std::string backend = "cpu";    // which renderer draws the image
  int width = 400;                // image width, pixels
  std::string aspect = "16:9";    // width:height or a decimal
  std::string output;             // image path; .png or .ppm
  std::string ppm_format = "P3";  // P3 (ASCII, as the lesson) or P6 (binary)
  bool quiet = false;             // no summary line
};

camera make_camera(const render_options& o) {
  const double aspect = parse_aspect(o.aspect);
  try {
    return camera(aspect, o.width);
  } catch (const std::invalid_argument& e) {
    throw usage_error("--aspect " + o.aspect + " with --width " + std::to_string(o.width) + ": " +
                      e.what());
  }
}

int run_render(const render_options& o) {
  check_output_path(o.output, "--output");
  const scene s = builtin_scene(o.scene);
  const camera cam = make_camera(o);

  const auto start = std::chrono::steady_clock::now();
  const framebuffer fb = render_cpu(cam, make_world(s));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const ppm_encoding enc = o.ppm_format == "P6" ? ppm_encoding::binary_p6 : ppm_encoding::ascii_p3;
  write_image(quantize(fb), o.output, enc);
  if (!o.quiet) {
    std::fprintf(stderr, "rtvk: %s %dx%d on %s in %.3f s -> %s\n", s.name.c_str(), fb.width(),
                 fb.height(), o.backend.c_str(), seconds, o.output.c_str());
  }
  return 0;
}

}  // namespace

command_action add_render_command(CLI::App& app) {
  auto opts = std::make_shared<render_options>();
  CLI::App* cmd = app.add_subcommand("render", "Render a scene to an image file");
  cmd->add_option("--scene", opts->scene, "Built-in scene name")->capture_default_str();
  cmd->add_option("--backend", opts->backend, "Renderer")
      ->check(CLI::IsMember({"cpu"}))
      ->capture_default_str();
  cmd->add_option("--width", opts->width, "Image width in pixels")
      ->check(CLI::Range(1, max_image_side))
      ->capture_default_str();
  cmd->add_option("--aspect", opts->aspect, "Aspect ratio, W:H or a decimal")
      ->capture_default_str();
  cmd->add_option("-o,--output", opts->output, "Output image (.png or .ppm)")->required();
  cmd->add_option("--ppm-format", opts->ppm_format, "PPM flavour: P3 (ASCII) or P6 (binary)")
      ->transform(CLI::IsMember({"P3", "P6"}, CLI::ignore_case))
      ->capture_default_str();
  cmd->add_flag("-q,--quiet", opts->quiet, "Print nothing on success");
  return [opts] { return run_render(*opts); };
}

}  // namespace rtvk
