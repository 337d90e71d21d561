#include "render_cpu.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>

#include "bvh_world.h"
#include "elapsed.h"
#include "errors.h"
#include "fast_render.h"
#include "light_sources.h"
#include "packing.h"
#include "parallel.h"
#include "random.h"
#include "render_aov.h"
#include "shading.h"
#include "world.h"

namespace rtvk {
namespace {

// A hittable that counts the rays traced through it, for `rtvk bench`.
class counting_world final : public hittable {
 public:
  explicit counting_world(const hittable& inner) : inner_(inner) {}
  bool hit(const ray& r, double t_min, double t_max, hit_record& rec) const override {
    ++rays;
    return inner_.hit(r, t_min, t_max, rec);
  }
  mutable std::uint64_t rays = 0;  // one thread's count

 private:
  const hittable& inner_;
};

// What every pixel of one render reads.
struct pixel_inputs {
  const camera& cam;             // sets the image size and casts the rays
  const rtvk::sky& sky;          // what rays that escape see
  const render_settings& rs;     // seed, jitter and bounce limit
  const scene_shading& shading;  // the scene's materials, textures and media
  const render_window& win;      // the samples to take
  std::uint32_t strata;          // pixel_strata: the cells a side the samples spread over
  bool low_discrepancy;          // Sobol numbers in every dimension (next-event estimation)
};

// Whether a sample's color can be added: a NaN or an infinity (a lamp past float's range, an
// overflow along a path) would spoil the pixel's sum. The GPU tells them apart by
// their float bits (fixed_sum.h); here in double, and past float's range counts as infinite.
bool finite_sample(const color& c) {
  const double most = 3.4028234663852886e38;  // FLT_MAX
  for (int k = 0; k < 3; ++k)
    if (!(std::abs(c[k]) <= most)) return false;
  return true;
}

// The mean of pixel (i, y)'s samples [win.sample_begin, win.sample_end), y counted from the top.
color pixel_color(const pixel_inputs& in, const hittable& world, int i, int y,
                  std::uint64_t& dropped) {
  const int width = in.cam.image_width();
  const int height = in.cam.image_height();
  const int j = height - 1 - y;  // the lesson counts rows from the bottom
  color sum(0, 0, 0);
  for (int sample = in.win.sample_begin; sample < in.win.sample_end; ++sample) {
    const random_stream hashed =
        pixel_sample_stream(in.rs.seed, uint(y) * uint(width) + uint(i), uint(sample));
    const random_stream rnd = in.low_discrepancy ? with_low_discrepancy(hashed) : hashed;
    const ray r = sample_ray(in.cam.frame(), uint(width), uint(height), uint(i), uint(j), rnd,
                             in.rs.jitter, true, in.strata, uint(sample));
    const color c = ray_color(r, world, in.shading, in.sky, in.rs.max_depth, rnd);
    if (finite_sample(c))
      sum += c;
    else
      ++dropped;
  }
  return divide(sum, in.win.samples());
}

// The fast mode's settings for a render: the camera and the settings as the GPU's push constants
// and camera buffer hold them.
fast_settings fast_settings_of(const camera& cam, const scene& s, const render_settings& rs) {
  fast_settings f;
  f.camera = gpu::to_ubo(cam);
  f.horizon = glm::vec3(s.sky.horizon);
  f.zenith = glm::vec3(s.sky.zenith);
  f.seed = rs.seed;
  f.max_depth = std::uint32_t(rs.max_depth);
  f.sample_lights = samples_lights(s, rs);
  f.nee = uses_nee(rs.sampling);
  f.strata = pixel_strata(rs, f.sample_lights);
  f.jitter = rs.jitter;
  return f;
}

}  // namespace

int worker_threads(int threads) {
  if (threads > 0) return threads;
  return int(std::max(1u, std::thread::hardware_concurrency()));
}

framebuffer render_cpu(const camera& cam, const scene& s, const render_settings& rs,
                       const progress_callback& progress, const engine_options& engine,
                       render_stats* stats) {
  return render_cpu_window(cam, s, rs, whole_render(cam.image_width(), cam.image_height(), rs.spp),
                           progress, engine, stats);
}

framebuffer render_cpu_window(const camera& cam, const scene& s, const render_settings& rs,
                              const render_window& win, const progress_callback& progress,
                              const engine_options& engine, render_stats* stats) {
  check_window(win, cam.image_width(), cam.image_height());  // before the world is built
  const cpu_scene prepared(s, engine);
  framebuffer fb = prepared.render(cam, rs, win, progress, engine, stats);
  if (stats) stats->build_seconds = prepared.build_seconds();
  return fb;
}

cpu_scene::cpu_scene(const scene& s, const engine_options& engine) : s_(s) {
  const auto build_start = std::chrono::steady_clock::now();
  if (runs_fast(engine))  // Embree builds the trees over the GPU's arrays, without their BVH
    fast_ = std::make_unique<fast_scene>(gpu::build_scene_arrays(s, false), float(s.motion.lo),
                                         float(s.motion.hi));
  else
    world_ = make_accelerated_world(s, engine.use_bvh, engine.threads);
  build_seconds_ = seconds_since(build_start);
}

cpu_scene::~cpu_scene() = default;

const scene_shading& cpu_scene::shading(bool sample_lights, bool nee) const {
  const std::lock_guard lock(mutex_);
  std::unique_ptr<scene_shading>& kept = shading_[std::size_t(sample_lights) + 2u * nee];
  if (!kept) kept = std::make_unique<scene_shading>(s_, sample_lights, nee);
  return *kept;
}

framebuffer cpu_scene::render(const camera& cam, const render_settings& rs,
                              const render_window& win, const progress_callback& progress,
                              const engine_options& engine, render_stats* stats) const {
  check_window(win, cam.image_width(), cam.image_height());
  check_motion_span(s_.motion, scene_moves(s_), cam);
  if (fast_) return fast_->render(fast_settings_of(cam, s_, rs), win, progress, engine, stats);
  return render_reference(cam, rs, win, progress, engine, stats);
}

framebuffer cpu_scene::render_reference(const camera& cam, const render_settings& rs,
                                        const render_window& win, const progress_callback& progress,
                                        const engine_options& engine, render_stats* stats) const {
  const bool lights = samples_lights(s_, rs);
  const bool nee = uses_nee(rs.sampling);
  const pixel_inputs in{cam, s_.sky, rs, shading(lights, nee), win, pixel_strata(rs, lights), nee};
  const hittable& world = *world_;
  framebuffer fb(win.width, win.height);
  const std::size_t width = std::size_t(win.width);
  std::atomic<std::uint64_t> rays{0};
  std::atomic<std::uint64_t> dropped{0};
  parallel_pixels(
      win.width, win.height, worker_threads(engine.threads), engine.cancelled, progress,
      [&](std::size_t begin, std::size_t end) {
        const counting_world counted(world);
        // Counting costs a virtual call per ray: only when someone asked for it.
        const hittable& target = engine.count_rays ? static_cast<const hittable&>(counted) : world;
        std::uint64_t chunk_dropped = 0;
        for (std::size_t p = begin; p < end; ++p) {
          const int row = int(p / width), column = int(p % width);
          fb.at(column, row) = pixel_color(in, target, win.x + column, win.y + row, chunk_dropped);
        }
        rays += counted.rays;
        dropped += chunk_dropped;
      });
  if (stats) *stats = {.rays = rays.load(), .dropped_samples = dropped.load()};
  return fb;
}

std::vector<gpu::gpu_aov> cpu_scene::aovs(const camera& cam, const render_window& win,
                                          int threads) const {
  const bvh_world* world = dynamic_cast<const bvh_world*>(world_.get());
  if (!world) {
    const std::lock_guard lock(mutex_);
    if (!aov_world_) aov_world_ = std::make_unique<bvh_world>(s_, threads);
    world = aov_world_.get();
  }
  return render_aov_cpu(cam, *world, shading(false, false), win, threads);
}

}  // namespace rtvk
