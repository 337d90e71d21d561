#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "atomic_file.h"
#include "commands.h"
#include "context.h"
#include "elapsed.h"
#include "errors.h"
#include "gpu_engine.h"
#include "gpu_flags.h"
#include "interrupt.h"
#include "light_sources.h"
#include "pipeline_cache.h"
#include "precision_flag.h"
#include "render_cpu.h"
#include "render_gpu.h"
#include "render_memory.h"
#include "scene_file.h"
#include "scene_flags.h"
#include "vk_error.h"

namespace rtvk {
namespace {

struct bench_options {
  std::string scene = "book-final";  // what to render
  std::string backend = "all";       // cpu, gpu or all
  int threads = 0;                   // CPU threads; 0: one per core
  std::string accel = "bvh";         // bvh, none, rt-query, rt-pipeline or auto
  std::string precision = "auto";    // the CPU's mode: auto, fast, reference or both
  gpu_flags gpu;                     // --device, --validate, --gpu-timeout
  int repeat = 1;                    // timed runs per backend, after one warm-up
  std::string json;                  // write the records here too
  scene_flags flags;                 // --width, --spp, --depth, ...
};

// One timed render, as `rtvk bench` reports it.
struct bench_record {
  std::string scene, backend, device;
  int threads = 0, width = 0, height = 0, spp = 0, depth = 0;
  std::uint64_t rays = 0;
  std::uint64_t dropped = 0;  // samples with a NaN or infinite channel (added black)
  std::string sampling;       // plain, lights or nee
  std::string accel;          // what found the hits: bvh, none, rt-query, rt-pipeline, embree
  std::string precision;      // CPU: fast or reference (--precision); the GPU's: float
  double seconds = 0;         // the whole render, BVH build included (CPU; the GPU builds it once)
  double build_seconds = 0;   // of which building the BVH
  double setup_seconds = -1;  // GPU: setting up the engine (limits, BVH, uploads), once a run
  double first_sample_seconds = -1;  // GPU: from the engine's set-up to the first sample's end
  double gpu_seconds = -1;  // GPU: device time of the render (timestamp queries); 0: unknown
  double mrays_per_s() const { return seconds > 0 ? double(rays) / seconds / 1e6 : 0; }
};

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown CPU";
}

void print(const bench_record& r) {
  char setup[128];
  if (r.setup_seconds >= 0)
    std::snprintf(setup, sizeof setup,
                  "device time %.3f s; set-up %.3f s once, first sample after %.3f s",
                  r.gpu_seconds, r.setup_seconds, r.first_sample_seconds);
  else
    std::snprintf(setup, sizeof setup, "BVH build %.3f s", r.build_seconds);
  std::printf(
      "%-4s %s %dx%d, %d spp, depth %d%s: %.1f M rays in %.3f s (%s) = %.2f Mrays/s (%s%s)\n",
      r.backend.c_str(), r.scene.c_str(), r.width, r.height, r.spp, r.depth,
      r.sampling == "lights" ? ", lights sampling"
      : r.sampling == "nee"  ? ", nee sampling"
                             : "",
      double(r.rays) / 1e6, r.seconds, setup, r.mrays_per_s(),
      (r.device + ", accel " + r.accel + (r.backend == "cpu" ? ", " + r.precision : "")).c_str(),
      r.backend == "cpu" ? (", " + std::to_string(r.threads) + " threads").c_str() : "");
  if (r.dropped > 0)
    std::printf("     %llu samples were NaN or infinite and added black\n",
                static_cast<unsigned long long>(r.dropped));
  std::fflush(stdout);
}

// Runs `render` once to warm up, then `repeat` times timed; each record starts from `base` as
// it is after the warm-up.
template <typename Render>
void measure(int repeat, const bench_record& base, Render render, std::vector<bench_record>& out) {
  render_stats stats;
  render(stats);
  for (int k = 0; k < repeat; ++k) {
    const auto start = std::chrono::steady_clock::now();
    render(stats);
    bench_record r = base;
    r.seconds = seconds_since(start);
    r.rays = stats.rays;
    r.dropped = stats.dropped_samples;
    if (base.setup_seconds < 0) r.build_seconds = stats.build_seconds;  // the GPU builds it once
    if (base.gpu_seconds >= 0) r.gpu_seconds = stats.gpu_seconds;
    print(r);
    out.push_back(r);
  }
}

// Refuses a --json path whose folder does not exist before any time is spent rendering.
void check_json_folder(const std::string& path) {
  const std::filesystem::path json(path);
  const auto dir = json.has_parent_path() ? json.parent_path() : std::filesystem::path(".");
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec))
    throw usage_error("--json: folder '" + dir.string() + "' of '" + path + "' does not exist");
}

engine_options engine_from(const bench_options& o) {
  if ((o.accel == "rt-query" || o.accel == "rt-pipeline") && o.backend == "cpu")
    throw usage_error("--accel " + o.accel +
                      ": the device's hardware ray tracing; needs --backend gpu or all");
  engine_options engine;
  engine.use_bvh = o.accel != "none";
  engine.threads = o.threads;
  engine.count_rays = true;
  engine.cancelled = interrupt_requested();
  return engine;
}

// What every record of the run shares: the scene and the image drawn.
bench_record record_for(const scene& s, const camera& cam) {
  bench_record base;
  base.scene = s.name;
  base.width = cam.image_width();
  base.height = cam.image_height();
  base.spp = s.render.spp;
  base.depth = s.render.max_depth;
  base.sampling = uses_nee(s.render.sampling)   ? "nee"
                  : samples_lights(s, s.render) ? "lights"
                                                : "plain";
  return base;
}

// Times the CPU render; `b` is the run's shared record, completed here with the CPU's fields.
void bench_cpu(const bench_options& o, bench_record b, const camera& cam, const scene& s,
               const engine_options& engine, std::vector<bench_record>& records) {
  b.backend = "cpu";
  const bool fast = runs_fast(engine);
  b.precision = fast ? "fast" : "reference";
  b.accel = fast ? "embree" : engine.use_bvh ? "bvh" : "none";
  b.device = cpu_model();
  b.threads = worker_threads(o.threads);
  measure(
      o.repeat, b, [&](render_stats& st) { render_cpu(cam, s, s.render, {}, engine, &st); },
      records);
}

// Times the GPU render, as bench_cpu. Without a Vulkan device --backend all goes on (saying so)
// and --backend gpu fails.
void bench_gpu(const bench_options& o, bench_record b, const camera& cam, const scene& s,
               const engine_options& engine, std::vector<bench_record>& records) {
  const gpu::gpu_options g = o.gpu.options(wants_ray_tracing(o.accel));
  std::unique_ptr<gpu::gpu_context> ctx;
  try {
    ctx = std::make_unique<gpu::gpu_context>(g);
  } catch (const gpu::no_device_error& e) {
    if (o.backend == "gpu") throw;
    std::fprintf(stderr, "rtvk: note: no Vulkan device (%s); GPU not measured\n", e.what());
  }
  if (!ctx) return;
  b.backend = "gpu";
  b.precision = "float";
  const auto& d = ctx->device();
  b.device = d.name + ", driver " + gpu::driver_string(d) +
             (g.validate ? ", validation layer on" : "");  // slower: the record says so
  // The engine is set up once, as a run of `rtvk render` does; the timed renders reuse it.
  engine_options on_device = engine;
  on_device.traversal = traversal_for(o.accel, *ctx);
  const auto start = std::chrono::steady_clock::now();
  gpu::gpu_engine gpu_scene(
      *ctx, s, {.engine = on_device, .pipeline_cache_folder = gpu::default_cache_folder()});
  b.accel = gpu_scene.traversal_name();
  b.setup_seconds = gpu_scene.setup_seconds();
  b.gpu_seconds = 0;
  b.build_seconds = gpu_scene.build_seconds();
  const render_window all = whole_render(cam.image_width(), cam.image_height(), s.render.spp);
  measure(
      o.repeat, b,
      [&](render_stats& st) {
        // The first progress call comes when the first submission's samples are done.
        const auto first_sample = [&](int) {
          if (b.first_sample_seconds < 0) b.first_sample_seconds = seconds_since(start);
        };
        gpu_scene.render_views({cam}, s.render, all, first_sample, &st);
      },
      records);
  ctx->check_validation();
}

void write_json(const std::string& path, const std::vector<bench_record>& records) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const auto& r : records)
    out.push_back({{"scene", r.scene},
                   {"backend", r.backend},
                   {"device", r.device},
                   {"threads", r.threads},
                   {"width", r.width},
                   {"height", r.height},
                   {"spp", r.spp},
                   {"depth", r.depth},
                   {"rays", r.rays},
                   {"sampling", r.sampling},
                   {"accel", r.accel},
                   {"precision", r.precision},
                   {"dropped_samples", r.dropped},
                   {"seconds", r.seconds},
                   {"build_seconds", r.build_seconds},
                   {"setup_seconds", r.setup_seconds >= 0 ? nlohmann::json(r.setup_seconds)
                                                          : nlohmann::json(nullptr)},
                   {"first_sample_seconds", r.first_sample_seconds >= 0
                                                ? nlohmann::json(r.first_sample_seconds)
                                                : nlohmann::json(nullptr)},
                   {"gpu_seconds",
                    r.gpu_seconds >= 0 ? nlohmann::json(r.gpu_seconds) : nlohmann::json(nullptr)},
                   {"mrays_per_s", r.mrays_per_s()}});
  write_file_atomically(path, out.dump(2) + "\n");
}

int run_bench(bench_options& o) {
  const interrupt_guard signals;  // SIGINT, SIGTERM: stop at the next pass, exit 128 + signal
  if (!o.json.empty()) check_json_folder(o.json);
  scene s = load_scene(o.scene, o.flags.access());
  // What the loaders drew otherwise than the files ask (a missing MTL drawn gray), said once.
  for (const std::string& w : s.warnings) std::fprintf(stderr, "rtvk: warning: %s\n", w.c_str());
  check_scene(s);
  const scene_overrides overrides = o.flags.overrides();
  overrides.apply_cameras(s);  // --colmap's views, a calibration's size
  s.cameras.resize(1);         // bench draws the scene's (or the model's) first camera at time 0
  overrides.apply(s);
  const camera cam = overrides.make_camera(s, main_camera(s).at(0),
                                           "camera " + s.cameras[0].name + " of " + o.scene);
  s.motion = {cam.time_open(), cam.time_close()};  // the instants its BVHs bound spheres over
  check_render_memory(cam.image_width(), cam.image_height(), 1);
  const engine_options engine = engine_from(o);
  const bench_record base = record_for(s, cam);
  std::vector<bench_record> records;
  if (o.backend == "cpu" || o.backend == "all") {
    // --precision both: the fast mode, then the reference, in the same run.
    const std::vector<cpu_precision> modes =
        o.precision == "both"
            ? std::vector<cpu_precision>{cpu_precision::fast, cpu_precision::reference}
            : std::vector<cpu_precision>{precision_for(o.precision, o.scene)};
    for (const cpu_precision mode : modes) {
      engine_options cpu = engine;
      cpu.precision = mode;
      bench_cpu(o, base, cam, s, cpu, records);
    }
  }
  if (o.backend == "gpu" || o.backend == "all") bench_gpu(o, base, cam, s, engine, records);
  if (!o.json.empty()) write_json(o.json, records);
  return 0;
}

}  // namespace

command_action add_bench_command(CLI::App& app) {
  auto o = std::make_shared<bench_options>();
  CLI::App* cmd = app.add_subcommand(
      "bench", "Time renders (after one warm-up) and report rays traced per second");
  cmd->add_option(
         "--scene", o->scene,
         "Built-in scene (also spheres:N), a .json scene file or a mesh (.obj, .gltf, .glb)")
      ->capture_default_str();
  cmd->add_option("--backend", o->backend, "cpu, gpu or all")
      ->check(CLI::IsMember({"cpu", "gpu", "all"}))
      ->capture_default_str();
  cmd->add_option("--threads", o->threads, "CPU threads (0: one per core)")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str();
  cmd->add_option("--accel", o->accel, accel_flag_help)
      ->check(CLI::IsMember(accel_words()))
      ->capture_default_str();
  add_precision_option(*cmd, o->precision, true);
  o->gpu.add_to(*cmd);
  cmd->add_option("--repeat", o->repeat, "Timed runs per backend")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  cmd->add_option("--json", o->json, "Also write one JSON record per run to this file");
  o->flags.add_to(*cmd);
  return [o] { return run_bench(*o); };
}

}  // namespace rtvk
