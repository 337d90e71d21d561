#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>

#include "camera.h"
#include "commands.h"
#include "errors.h"
#include "format.h"
#include "gpu/context.h"
#include "gpu/render_gpu.h"
#include "gpu/vk_error.h"
#include "image_compare.h"
#include "image_io.h"
#include "interrupt.h"
#include "memory_check.h"
#include "progress.h"
#include "quantize.h"
#include "render_cpu.h"
#include "scene.h"
#include "scene_file.h"
#include "scene_flags.h"

namespace rtvk {
namespace {

struct render_options {
  std::string scene = "seed";     // built-in scene name or .json file
  std::string backend = "cpu";    // cpu, gpu, auto or both
  std::string output;             // image path; .png or .ppm
  std::string ppm_format = "P3";  // P3 (ASCII, as the lesson) or P6 (binary)
  std::string device;             // GPU selector: index or name substring
  bool validate = false;          // Vulkan validation layer on
  bool quiet = false;             // no summary line, no progress bar
  std::string accel = "bvh";      // bvh or none
  int threads = 0;                // CPU threads; 0: one per core
  double gpu_timeout = 120;       // seconds one GPU submission may take
  scene_flags flags;              // --width, --spp, --lookfrom, ...
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A finished render: its pixels, the backend's name for the summary, and the time it took.
struct rendered {
  image_rgb8 image;     // quantized with the one shared rule
  std::string backend;  // "cpu" or "gpu (device name)"
  double seconds = 0;   // rendering only, not set-up or file output
};

engine_options engine_from(const render_options& o) {
  engine_options e;
  e.use_bvh = o.accel == "bvh";
  e.threads = o.threads;
  e.cancelled = interrupt_requested();
  return e;
}

rendered draw_cpu(const render_options& o, const camera& cam, const scene& s) {
  progress_bar bar("rendering on the CPU", cam.image_height(), !o.quiet);
  const auto start = std::chrono::steady_clock::now();
  const framebuffer fb = render_cpu(
      cam, s, s.render, [&](int rows) { bar.update(rows); }, engine_from(o));
  bar.finish();
  return {quantize(fb, s.render.gamma), "cpu", seconds_since(start)};
}

rendered draw_gpu(const render_options& o, gpu::gpu_context& ctx, const camera& cam,
                  const scene& s) {
  progress_bar bar("rendering on the GPU", s.render.spp, !o.quiet);
  const auto start = std::chrono::steady_clock::now();
  const framebuffer fb = gpu::render_gpu(
      ctx, cam, s, s.render, [&](int samples) { bar.update(samples); }, engine_from(o));
  bar.finish();
  const double seconds = seconds_since(start);
  if (ctx.validation_messages() > 0)
    throw std::runtime_error("the Vulkan validation layer reported " +
                             std::to_string(ctx.validation_messages()) +
                             " problem(s) (above); no image written");
  return {quantize(fb, s.render.gamma), "gpu (" + ctx.device().name + ")", seconds};
}

gpu::gpu_options gpu_options_from(const render_options& o) {
  gpu::gpu_options g;
  g.device = o.device;
  const char* env = std::getenv("RTVK_VALIDATE");
  g.validate = o.validate || (env && std::string(env) == "1");
  g.fence_timeout =
      std::chrono::milliseconds(std::max<long long>(1, std::llround(o.gpu_timeout * 1000)));
  return g;
}

// Writes the image, unless a signal arrived while rendering finished: Ctrl-C means no file.
void write_unless_interrupted(const image_rgb8& img, const std::string& path, ppm_encoding enc) {
  if (pending_signal() != 0) throw render_cancelled("the render had finished");
  write_image(img, path, enc);
}

void summarize(const render_options& o, const scene& s, const rendered& r) {
  if (o.quiet) return;
  std::fprintf(stderr, "rtvk: %s %dx%d, %d spp, on %s in %.3f s -> %s\n", s.name.c_str(),
               r.image.width, r.image.height, s.render.spp, r.backend.c_str(), r.seconds,
               o.output.c_str());
}

// Deterministic scenes (one sample, no jitter, no lens, normal shading) must agree to a level;
// Monte Carlo ones to the noise rule.
agreement agreement_for(const scene& s, const camera& cam) {
  bool deterministic = s.render.spp == 1 && !s.render.jitter && cam.lens_radius() == 0;
  for (const auto& m : s.materials) deterministic &= m.m.type == material_type::normal;
  return deterministic ? agreement{} : monte_carlo_agreement;
}

// --backend both: the GPU image is written; the exit status says whether the CPU agrees.
int render_both(const render_options& o, const camera& cam, const scene& s, ppm_encoding enc) {
  gpu::gpu_context ctx(gpu_options_from(o));
  const rendered gpu_image = draw_gpu(o, ctx, cam, s);
  const rendered cpu_image = draw_cpu(o, cam, s);
  const agreement rule = agreement_for(s, cam);
  const image_difference d = compare_images(gpu_image.image, cpu_image.image, rule.tolerance);
  write_unless_interrupted(gpu_image.image, o.output, enc);
  summarize(o, s, gpu_image);
  const bool ok = agrees(d, rule);
  std::fprintf(stderr,
               "rtvk: gpu vs cpu (%.3f s): %s -- PSNR %.1f dB, max %d levels, mean %.4f, %.4f%% "
               "of pixels over %d (allowed %.2f%%)\n",
               cpu_image.seconds, ok ? "alike" : "DIFFERENT", d.psnr_db, d.max_abs, d.mean_abs,
               100 * d.share_over, rule.tolerance, 100 * rule.max_share);
  return ok ? 0 : 1;
}

int run_render(render_options o) {
  const interrupt_guard signals;  // SIGINT, SIGTERM: stop at the next pass, exit 128 + signal
  check_output_path(o.output, "--output");
  if (!o.device.empty() && o.backend == "cpu")
    throw usage_error("--device " + o.device + ": needs --backend gpu, auto or both");
  scene s = load_scene(o.scene);
  check_scene(s);
  o.flags.apply(s);
  const camera cam = o.flags.make_camera(s, o.scene);
  check_render_memory(cam.image_width(), cam.image_height(), o.backend == "both" ? 2 : 1);
  const ppm_encoding enc = o.ppm_format == "P6" ? ppm_encoding::binary_p6 : ppm_encoding::ascii_p3;

  if (o.backend == "both") return render_both(o, cam, s, enc);
  std::optional<rendered> result;
  if (o.backend == "cpu") {
    result = draw_cpu(o, cam, s);
  } else {
    std::unique_ptr<gpu::gpu_context> ctx;
    try {
      ctx = std::make_unique<gpu::gpu_context>(gpu_options_from(o));
    } catch (const gpu::no_device_error& e) {
      if (o.backend != "auto") throw;
      std::fprintf(stderr, "rtvk: note: no Vulkan device (%s); rendering on the CPU\n", e.what());
    }
    result = ctx ? draw_gpu(o, *ctx, cam, s) : draw_cpu(o, cam, s);
  }
  write_unless_interrupted(result->image, o.output, enc);
  summarize(o, s, *result);
  return 0;
}

}  // namespace

command_action add_render_command(CLI::App& app) {
  auto o = std::make_shared<render_options>();
  CLI::App* cmd = app.add_subcommand("render", "Render a scene to an image file");
  cmd->add_option("--scene", o->scene,
                  "Built-in scene (seed, materials, book-final) or a .json scene file")
      ->capture_default_str();
  cmd->add_option("--backend", o->backend,
                  "cpu (reference), gpu (Vulkan), auto (gpu if a device exists, else cpu), "
                  "both (gpu, checked against cpu)")
      ->check(CLI::IsMember({"cpu", "gpu", "auto", "both"}))
      ->capture_default_str();
  cmd->add_option("-o,--output", o->output, "Output image (.png or .ppm)")->required();
  cmd->add_option("--ppm-format", o->ppm_format, "PPM flavour: P3 (ASCII) or P6 (binary)")
      ->transform(CLI::IsMember({"P3", "P6"}, CLI::ignore_case))
      ->capture_default_str();
  cmd->add_option("--device", o->device,
                  "Vulkan device: an index or part of its name (see rtvk devices)");
  cmd->add_flag("--validate", o->validate,
                "Enable VK_LAYER_KHRONOS_validation (also RTVK_VALIDATE=1)");
  cmd->add_flag("-q,--quiet", o->quiet, "No summary line and no progress bar");
  cmd->add_option("--accel", o->accel, "bvh, or none to test every sphere (same image, slower)")
      ->check(CLI::IsMember({"bvh", "none"}))
      ->capture_default_str();
  cmd->add_option("--gpu-timeout", o->gpu_timeout,
                  "Seconds one GPU submission may take before the device counts as hung")
      ->check(CLI::Range(0.001, 86400.0))
      ->capture_default_str();
  cmd->add_option("--threads", o->threads, "CPU threads (0: one per core)")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str();

  o->flags.add_to(*cmd);
  return [o] { return run_render(*o); };
}

}  // namespace rtvk
