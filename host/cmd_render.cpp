#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "aspect.h"
#include "camera.h"
#include "commands.h"
#include "errors.h"
#include "gpu/context.h"
#include "gpu/render_gpu.h"
#include "gpu/vk_error.h"
#include "image_compare.h"
#include "image_io.h"
#include "quantize.h"
#include "render_cpu.h"
#include "scene.h"

namespace rtvk {
namespace {

struct render_options {
  std::string scene = "seed";     // built-in scene name
  std::string backend = "cpu";    // cpu, gpu, auto or both
  int width = 400;                // image width, pixels
  std::string aspect = "16:9";    // width:height or a decimal
  std::string output;             // image path; .png or .ppm
  std::string ppm_format = "P3";  // P3 (ASCII, as the lesson) or P6 (binary)
  std::string device;             // GPU selector: index or name substring
  bool validate = false;          // Vulkan validation layer on
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

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A finished render: its pixels, the backend's name for the summary, and the time it took.
struct rendered {
  image_rgb8 image;     // quantized with the one shared rule
  std::string backend;  // "cpu" or "gpu (device name)"
  double seconds = 0;   // rendering only, not set-up or file output
};

rendered draw_cpu(const camera& cam, const scene& s) {
  const auto start = std::chrono::steady_clock::now();
  const framebuffer fb = render_cpu(cam, make_world(s));
  return {quantize(fb), "cpu", seconds_since(start)};
}

rendered draw_gpu(gpu::gpu_context& ctx, const camera& cam, const scene& s) {
  const auto start = std::chrono::steady_clock::now();
  const framebuffer fb = gpu::render_gpu(ctx, cam, s);
  const double seconds = seconds_since(start);
  if (ctx.validation_messages() > 0)
    throw std::runtime_error("the Vulkan validation layer reported " +
                             std::to_string(ctx.validation_messages()) +
                             " problem(s) (above); no image written");
  return {quantize(fb), "gpu (" + ctx.device().name + ")", seconds};
}

gpu::gpu_options gpu_options_from(const render_options& o) {
  gpu::gpu_options g;
  g.device = o.device;
  const char* env = std::getenv("RTVK_VALIDATE");
  g.validate = o.validate || (env && std::string(env) == "1");
  return g;
}

void summarize(const render_options& o, const scene& s, const rendered& r) {
  if (o.quiet) return;
  std::fprintf(stderr, "rtvk: %s %dx%d on %s in %.3f s -> %s\n", s.name.c_str(), r.image.width,
               r.image.height, r.backend.c_str(), r.seconds, o.output.c_str());
}

// --backend both: the GPU image is written; the exit status says whether the CPU agrees.
int render_both(const render_options& o, const camera& cam, const scene& s, ppm_encoding enc) {
  gpu::gpu_context ctx(gpu_options_from(o));
  const rendered gpu_image = draw_gpu(ctx, cam, s);
  const rendered cpu_image = draw_cpu(cam, s);
  const agreement rule;
  const image_difference d = compare_images(gpu_image.image, cpu_image.image, rule.tolerance);
  write_image(gpu_image.image, o.output, enc);
  summarize(o, s, gpu_image);
  const bool ok = agrees(d, rule);
  std::fprintf(stderr,
               "rtvk: gpu vs cpu: %s -- max %d levels, mean %.4f, %.4f%% of pixels over %d "
               "(allowed %.2f%%)\n",
               ok ? "alike" : "DIFFERENT", d.max_abs, d.mean_abs, 100 * d.share_over,
               rule.tolerance, 100 * rule.max_share);
  return ok ? 0 : 1;
}

int run_render(const render_options& o) {
  check_output_path(o.output, "--output");
  if (!o.device.empty() && o.backend == "cpu")
    throw usage_error("--device " + o.device + ": needs --backend gpu, auto or both");
  const scene s = builtin_scene(o.scene);
  const camera cam = make_camera(o);
  const ppm_encoding enc = o.ppm_format == "P6" ? ppm_encoding::binary_p6 : ppm_encoding::ascii_p3;

  if (o.backend == "both") return render_both(o, cam, s, enc);
  std::optional<rendered> result;
  if (o.backend == "cpu") {
    result = draw_cpu(cam, s);
  } else {
    std::unique_ptr<gpu::gpu_context> ctx;
    try {
      ctx = std::make_unique<gpu::gpu_context>(gpu_options_from(o));
    } catch (const gpu::no_device_error& e) {
      if (o.backend != "auto") throw;
      std::fprintf(stderr, "rtvk: note: no Vulkan device (%s); rendering on the CPU\n", e.what());
    }
    result = ctx ? draw_gpu(*ctx, cam, s) : draw_cpu(cam, s);
  }
  write_image(result->image, o.output, enc);
  summarize(o, s, *result);
  return 0;
}

}  // namespace

command_action add_render_command(CLI::App& app) {
  auto opts = std::make_shared<render_options>();
  CLI::App* cmd = app.add_subcommand("render", "Render a scene to an image file");
  cmd->add_option("--scene", opts->scene, "Built-in scene name")->capture_default_str();
  cmd->add_option("--backend", opts->backend,
                  "cpu (reference), gpu (Vulkan), auto (gpu if a device exists, else cpu), "
                  "both (gpu, checked against cpu)")
      ->check(CLI::IsMember({"cpu", "gpu", "auto", "both"}))
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
  cmd->add_option("--device", opts->device,
                  "Vulkan device: an index or part of its name (see rtvk devices)");
  cmd->add_flag("--validate", opts->validate,
                "Enable VK_LAYER_KHRONOS_validation (also RTVK_VALIDATE=1)");
  cmd->add_flag("-q,--quiet", opts->quiet, "Print nothing on success");
  return [opts] { return run_render(*opts); };
}

}  // namespace rtvk
