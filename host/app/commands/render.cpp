#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "aov_output.h"
#include "aov_pass.h"
#include "camera.h"
#include "commands.h"
#include "context.h"
#include "elapsed.h"
#include "errors.h"
#include "format.h"
#include "gpu_engine.h"
#include "gpu_flags.h"
#include "image_compare.h"
#include "image_io.h"
#include "interrupt.h"
#include "job_flags.h"
#include "light_sources.h"
#include "partial_image.h"
#include "pipeline_cache.h"
#include "precision_flag.h"
#include "progress.h"
#include "quantize.h"
#include "render_cpu.h"
#include "render_gpu.h"
#include "render_jobs.h"
#include "render_memory.h"
#include "scene.h"
#include "scene_file.h"
#include "scene_flags.h"
#include "shaders.h"
#include "shared_types.h"
#include "version.h"
#include "vk_error.h"

namespace rtvk {
namespace {

struct render_options {
  std::string scene = "seed";      // built-in scene name or .json file
  std::string backend = "cpu";     // cpu, gpu, auto or both
  job_request jobs;                // cameras, frames, region, samples and the -o pattern
  std::string ppm_format = "P3";   // P3 (ASCII, as the lesson) or P6 (binary)
  bool quiet = false;              // no summary line, no progress bar
  std::string accel = "bvh";       // bvh, none, rt-query, rt-pipeline or auto (accel_words)
  int threads = 0;                 // CPU threads; 0: one per core
  std::string precision = "auto";  // the CPU's mode: auto, fast or reference (precision_flag.h)
  gpu_flags gpu;                   // --device, --validate, --gpu-timeout
  scene_flags flags;               // --width, --spp, --lookfrom, ...
  std::string aov;                 // --aov: comma-separated aov_names()
};

engine_options engine_from(const render_options& o) {
  engine_options e;
  e.use_bvh = o.accel != "none";  // the CPU walks its BVH on every other path
  e.threads = o.threads;
  e.precision = precision_for(o.precision, o.scene);
  e.cancelled = interrupt_requested();
  return e;
}

// Everything a run shares between its images.
struct run_context {
  const render_options& o;
  const scene& s;
  const render_window& win;
  ppm_encoding enc;
  bool several;          // more than one image: each summary line names its camera and frame
  std::size_t* written;  // images finished and written so far
  bool lights, nee;      // lights sampling, next-event estimation: for the summaries
  unsigned aovs = 0;     // --aov's aov_bit mask; 0: none
  // What the AOV pass of the backend that drew the image found (set where aovs != 0), and
  // whether the CPU agreed with the device's (--backend both).
  std::function<std::vector<gpu::gpu_aov>(const render_job&)> aov_pass = {};
  bool* aovs_alike = nullptr;
  // The scene set up for the CPU, made at its first use and kept for every view and frame.
  std::function<const cpu_scene&()> cpu = {};
};

std::string label(const run_context& run, const render_job& job) {
  if (!run.several && job.frame == 0) return run.s.name;
  return run.s.name + " [camera " + job.camera_name + ", frame " + std::to_string(job.frame) + "]";
}

// The render shader's SPIR-V, hashed: pieces drawn by different shaders do not merge unasked.
const std::string& render_shader_identity() {
  static const std::string id = [] {
    const std::span<const std::uint32_t> spv = gpu::render_shader();
    return fingerprint_of(std::string(reinterpret_cast<const char*>(spv.data()), spv.size_bytes()));
  }();
  return id;
}

// Writes the image, unless a signal arrived while rendering finished: Ctrl-C means no file.
// .exr keeps the linear floats and the sample range for `rtvk merge`; .png and .ppm quantize.
// The job's AOVs, when asked for: drawn before its image is written, so a failure leaves no file.
std::optional<aov_image> job_aovs(const run_context& run, const render_job& job) {
  if (run.aovs == 0) return std::nullopt;
  return aov_from(run.aov_pass(job), object_ids(run.s), run.aovs, run.win);
}

// A PNG or PPM render's AOVs, each in its own OpenEXR file beside the image.
void write_aov_files(const run_context& run, const render_job& job, const aov_image& a) {
  for (aov_bit b : {aov_depth, aov_normal, aov_albedo, aov_object_id, aov_material_id})
    if (a.which & b)
      write_aov_exr(a, b, job.cam.image_width(), job.cam.image_height(), run.win,
                    aov_path(job.output, b));
}

void write_job(const run_context& run, const render_job& job, const framebuffer& fb) {
  if (pending_signal() != 0) throw render_cancelled("the render had finished");
  const std::optional<aov_image> aovs = job_aovs(run, job);
  if (format_for_path(job.output, "--output") == file_format::exr) {
    write_partial_exr(make_partial(fb, {job.cam.image_width(),
                                        job.cam.image_height(),
                                        run.win,
                                        {},
                                        run.s.render.gamma,
                                        job.fingerprint,
                                        run.s.name,
                                        job.camera_name,
                                        job.frame,
                                        version_string,
                                        render_shader_identity(),
                                        run.s.render.transform,
                                        run.s.render.exposure}),
                      job.output, aovs ? &*aovs : nullptr);
  } else {
    if (aovs) write_aov_files(run, job, *aovs);  // first: an image is never without its AOVs
    write_image(quantize(fb, run.s.render.encoding()), job.output, run.enc);
  }
  ++*run.written;
}

// Writes an image the GPU encoded to 8 bits itself, with the same Ctrl-C rule.
void write_job(const run_context& run, const render_job& job, const image_rgb8& img) {
  if (pending_signal() != 0) throw render_cancelled("the render had finished");
  const std::optional<aov_image> aovs = job_aovs(run, job);
  if (aovs) write_aov_files(run, job, *aovs);  // first: an image is never without its AOVs
  write_image(img, job.output, run.enc);
  ++*run.written;
}

// The summary line; `dropped`: samples with a NaN or infinite channel, which added black;
// `overflows`: of those, samples whose BVH walk overflowed its stack on the GPU.
void summarize(const run_context& run, const render_job& job, const std::string& backend,
               double seconds, std::uint64_t dropped, std::uint64_t overflows = 0) {
  if (run.o.quiet) return;
  std::fprintf(stderr, "rtvk: %s %dx%d, %d spp%s, on %s in %.3f s -> %s\n", label(run, job).c_str(),
               run.win.width, run.win.height, run.win.samples(),
               run.nee      ? " (nee sampling)"
               : run.lights ? " (lights sampling)"
                            : "",
               backend.c_str(), seconds, job.output.c_str());
  if (dropped > overflows)
    std::fprintf(stderr, "rtvk: %llu samples were NaN or infinite and added black\n",
                 static_cast<unsigned long long>(dropped - overflows));
  if (overflows > 0)
    std::fprintf(stderr,
                 "rtvk: %llu samples found the BVH walk's stack full and added black (a tree "
                 "deeper than the shader's stack)\n",
                 static_cast<unsigned long long>(overflows));
}

framebuffer draw_cpu(const run_context& run, const render_job& job, render_stats* stats = nullptr) {
  progress_bar bar("rendering on the CPU", run.win.height, !run.o.quiet);
  return run.cpu().render(
      job.cam, run.s.render, run.win, [&](int rows) { bar.update(rows); }, engine_from(run.o),
      stats);
}

// Shared submissions for a group of views (cameras, frames) of the run's one engine: each view's
// means (`encoded` false), or its 8-bit image encoded on the device.
struct gpu_group {
  std::vector<framebuffer> means;   // without `encoded`
  std::vector<image_rgb8> encoded;  // with it
};

gpu_group draw_gpu(const run_context& run, gpu::gpu_context& ctx, gpu::gpu_engine& engine,
                   std::span<const render_job> jobs, bool encoded, render_stats& stats) {
  progress_bar bar("rendering on the GPU", run.win.samples(), !run.o.quiet);
  std::vector<camera> views;
  for (const render_job& j : jobs) views.push_back(j.cam);
  const auto progress = [&](int samples) { bar.update(samples); };
  gpu_group out;
  if (encoded)
    out.encoded = engine.render_encoded(views, run.s.render, run.win, progress, &stats);
  else
    out.means = engine.render_views(views, run.s.render, run.win, progress, &stats);
  bar.finish();
  ctx.check_validation("; no image written");
  return out;
}

// Deterministic renders (one sample, no jitter, no lens, no material that draws random numbers,
// alpha blend included) must agree to a level; Monte Carlo ones to the noise rule.
agreement agreement_for(const run_context& run, const camera& cam) {
  bool deterministic = run.win.samples() == 1 && !run.s.render.jitter && cam.lens_radius() == 0;
  for (const auto& m : run.s.materials)  // a blend's passes draw random numbers too
    deterministic &= !kind_of(m.m.type).random && m.m.alpha != alpha_mode::blend;
  return deterministic ? agreement{} : monte_carlo_agreement;
}

// --backend both: the GPU image is written; the exit status says whether the CPU agrees.
bool check_against_cpu(const run_context& run, const render_job& job, const framebuffer& gpu_fb) {
  const auto start = std::chrono::steady_clock::now();
  const framebuffer cpu_fb = draw_cpu(run, job);
  const double cpu_seconds = seconds_since(start);
  const agreement rule = agreement_for(run, job.cam);
  const image_difference d =
      compare_images(quantize(gpu_fb, run.s.render.encoding()),
                     quantize(cpu_fb, run.s.render.encoding()), rule.tolerance);
  const bool ok = agrees(d, rule);
  std::fprintf(stderr,
               "rtvk: %sgpu vs cpu (%.3f s): %s -- PSNR %.1f dB, max %d levels, mean %.4f, %.4f%% "
               "of pixels over %d (allowed %.2f%%)\n",
               run.several ? (label(run, job) + ": ").c_str() : "", cpu_seconds,
               ok ? "alike" : "DIFFERENT", d.psnr_db, d.max_abs, d.mean_abs, 100 * d.share_over,
               rule.tolerance, 100 * rule.max_share);
  return ok;
}

int render_on_gpu(const run_context& cpu_run, gpu::gpu_context& ctx,
                  const std::vector<render_job>& jobs) {
  engine_options e = engine_from(cpu_run.o);
  e.traversal = traversal_for(cpu_run.o.accel, ctx);
  run_context run = cpu_run;
  const std::size_t group = gpu_group_size(run.win.width, run.win.height);
  // Set up once (scene buffers, BVH, pipelines) for every group of the run.
  gpu::gpu_engine engine(ctx, run.s,
                         {.engine = e, .pipeline_cache_folder = gpu::default_cache_folder()});
  // The AOVs on the device too; with --backend both, checked against the CPU's.
  bool aovs_alike = true;
  run.aovs_alike = &aovs_alike;
  // The AOVs through the render's own scene and tree, already on the device.
  std::unique_ptr<gpu::aov_pass> aovs;
  run.aov_pass = [&](const render_job& job) {
    if (!aovs)
      aovs = std::make_unique<gpu::aov_pass>(ctx, engine.device_scene(), engine.scene_has_bvh());
    std::vector<gpu::gpu_aov> found = aovs->run(job.cam, run.win);
    if (run.o.backend == "both")
      aovs_alike &=
          aovs_agree(found, run.cpu().aovs(job.cam, run.win, run.o.threads), object_ids(run.s),
                     run.win.width, run.several ? label(run, job) + ": " : "");
    return found;
  };
  // The summary says which device and which traversal drew the image.
  const std::string backend = "gpu (" + ctx.device().name + ", " + engine.traversal_name() + ")";
  // PNG and PPM are encoded on the device (4 bytes a pixel read back), unless the CPU's check
  // needs the means.
  const bool encoded = run.o.backend != "both" &&
                       format_for_path(jobs.front().output, "--output") != file_format::exr;
  bool all_alike = true;
  for (std::size_t first = 0; first < jobs.size(); first += group) {
    const std::span<const render_job> part(jobs.data() + first,
                                           std::min(group, jobs.size() - first));
    const auto start = std::chrono::steady_clock::now();
    render_stats stats;
    const gpu_group drawn = draw_gpu(run, ctx, engine, part, encoded, stats);
    const double seconds = seconds_since(start);
    for (std::size_t k = 0; k < part.size(); ++k) {
      if (encoded) {
        write_job(run, part[k], drawn.encoded[k]);
      } else {
        if (run.o.backend == "both") all_alike &= check_against_cpu(run, part[k], drawn.means[k]);
        write_job(run, part[k], drawn.means[k]);
      }
      summarize(run, part[k],
                part.size() > 1 ? backend + ", " + std::to_string(part.size()) + " views together"
                                : backend,
                seconds, k == 0 ? stats.dropped_samples : 0, k == 0 ? stats.stack_overflows : 0);
    }
  }
  return all_alike && aovs_alike ? 0 : 1;
}

// Every job on the backend asked for: GPU groups, or the CPU one job at a time.
int render_all(const run_context& run, const std::vector<render_job>& jobs) {
  const render_options& o = run.o;

  if (o.backend != "cpu") {
    std::unique_ptr<gpu::gpu_context> ctx;
    try {
      ctx = std::make_unique<gpu::gpu_context>(o.gpu.options(wants_ray_tracing(o.accel)));
    } catch (const gpu::no_device_error& e) {
      if (o.backend != "auto") throw;
      std::fprintf(stderr, "rtvk: note: no Vulkan device (%s); rendering on the CPU\n", e.what());
    }
    if (ctx) return render_on_gpu(run, *ctx, jobs);
  }
  for (const render_job& job : jobs) {
    const auto start = std::chrono::steady_clock::now();
    render_stats stats;
    const framebuffer fb = draw_cpu(run, job, &stats);
    const double seconds = seconds_since(start);
    write_job(run, job, fb);
    summarize(run, job, runs_fast(engine_from(o)) ? "cpu (fast)" : "cpu", seconds,
              stats.dropped_samples);
  }
  return 0;
}

int run_render(render_options o) {
  const interrupt_guard signals;  // SIGINT, SIGTERM: stop at the next pass, exit 128 + signal
  if (!o.gpu.device.empty() && o.backend == "cpu")
    throw usage_error("--device " + o.gpu.device + ": needs --backend gpu, auto or both");
  if ((o.accel == "rt-query" || o.accel == "rt-pipeline") && o.backend == "cpu")
    throw usage_error("--accel " + o.accel +
                      ": the device's hardware ray tracing; needs --backend gpu, auto or both");
  const output_pattern output(o.jobs.output, "--output");  // refused before the scene loads
  const unsigned aovs = aov_flag(o.aov);
  scene s = load_scene(o.scene, o.flags.access());
  check_scene(s);
  // What the loaders drew otherwise than the files ask (a missing MTL drawn gray), said once.
  for (const std::string& w : s.warnings) std::fprintf(stderr, "rtvk: warning: %s\n", w.c_str());
  render_window win;
  const std::vector<render_job> jobs = plan_jobs(s, o.jobs, output, o.flags.overrides(), win);
  for (const render_job& j : jobs) check_output_size(j.output, win.width, win.height, "--output");
  const std::size_t together = o.backend == "cpu" ? 1 : gpu_group_size(win.width, win.height);
  check_render_memory(win.width, win.height,
                      int(std::min(together, jobs.size())) * (o.backend == "both" ? 2 : 1));
  std::size_t written = 0;
  run_context run{o,
                  s,
                  win,
                  o.ppm_format == "P6" ? ppm_encoding::binary_p6 : ppm_encoding::ascii_p3,
                  jobs.size() > 1,
                  &written,
                  samples_lights(s, s.render),
                  uses_nee(s.render.sampling),
                  aovs};
  std::unique_ptr<cpu_scene> cpu;
  run.cpu = [&]() -> const cpu_scene& {
    if (!cpu) cpu = std::make_unique<cpu_scene>(s, engine_from(o));
    return *cpu;
  };
  run.aov_pass = [&](const render_job& job) { return run.cpu().aovs(job.cam, win, o.threads); };
  try {
    return render_all(run, jobs);
  } catch (const render_cancelled& e) {
    if (!run.several) throw;
    throw render_cancelled(std::string(e.what()) + " (" + std::to_string(written) + " of " +
                           std::to_string(jobs.size()) + " images were finished and written)");
  }
}

// The options that say how to draw and write them.
void add_engine_options(CLI::App& cmd, render_options& o) {
  cmd.add_option("--ppm-format", o.ppm_format, "PPM flavour: P3 (ASCII) or P6 (binary)")
      ->transform(CLI::IsMember({"P3", "P6"}, CLI::ignore_case))
      ->capture_default_str();
  o.gpu.add_to(cmd);
  cmd.add_flag("-q,--quiet", o.quiet, "No summary line and no progress bar");
  cmd.add_option("--accel", o.accel, accel_flag_help)
      ->check(CLI::IsMember(accel_words()))
      ->capture_default_str();
  cmd.add_option("--threads", o.threads, "CPU threads (0: one per core)")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str();
  add_precision_option(cmd, o.precision);
}

}  // namespace

command_action add_render_command(CLI::App& app) {
  auto o = std::make_shared<render_options>();
  CLI::App* cmd = app.add_subcommand("render", "Render a scene to an image file");
  cmd->add_option(
         "--scene,scene", o->scene,
         "Built-in scene (see rtvk scene list), a .json scene file or a mesh (.obj, .gltf, .glb)")
      ->capture_default_str();
  cmd->add_option("--backend", o->backend,
                  "cpu (--precision: fast or reference), gpu (Vulkan), auto (gpu if a device "
                  "exists, else cpu), "
                  "both (gpu, checked against cpu)")
      ->check(CLI::IsMember({"cpu", "gpu", "auto", "both"}))
      ->capture_default_str();
  add_job_options(*cmd, o->jobs);
  add_engine_options(*cmd, *o);
  cmd->add_option("--aov", o->aov,
                  "Ground truth beside the image, any of " + aov_names() +
                      ": what the ray through each pixel's center hits first, as extra "
                      "channels of an .exr output, else as OUT.NAME.exr files (docs/aov.md)")
      ->type_name("LIST");
  o->flags.add_to(*cmd);
  return [o] { return run_render(*o); };
}

}  // namespace rtvk
