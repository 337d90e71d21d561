#include "gpu_engine.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <deque>
#include <span>
#include <thread>

#include "band_commands.h"
#include "band_scheduler.h"
#include "compute_pipeline.h"
#include "elapsed.h"
#include "errors.h"
#include "format.h"
#include "gpu_scene.h"
#include "packing.h"
#include "parallel.h"
#include "ray_pipeline.h"
#include "readback.h"
#include "render_plan.h"
#include "render_targets.h"
#include "sample_sum.h"
#include "scene_accel.h"
#include "shaders.h"

namespace rtvk::gpu {
namespace {

// rt-pipeline's rays' times: a float per pixel of the targets (world_rt.glsl's ray_times).
std::unique_ptr<gpu_buffer> make_ray_times(const gpu_context& ctx, VkDeviceSize pixels) {
  return std::make_unique<gpu_buffer>(ctx, pixels * sizeof(float),
                                      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, memory_use::device_local);
}

// The iterations each path step counts, and on the hardware paths each traced ray besides its
// candidates, for the loops rtvk does not count -- a compute invocation's samples' own loop, the
// driver's traversal loop -- (render_push::trace_cost): one at first, doubled whenever an
// invocation ran into a driver's loop limit (limit_was_hit) all the same. On lavapipe 22.3 a
// compute invocation of tens of thousands of short samples (a tiny image at 2^20 samples) passes
// 65,535 trips with 60,000 counted: each doubling halves its samples until none is cut. Mesa 25's
// lavapipe was not seen to cut a traversal even with budgets past its limit
// (tests/gpu/test_gpu_hardware_rt.cpp); the guard is there for drivers that do.
constexpr std::uint32_t first_trace_cost = 1;

}  // namespace

gpu_engine::gpu_engine(gpu_context& ctx, const scene& s, const gpu_render_options& options)
    : start_(std::chrono::steady_clock::now()),
      ctx_(ctx),
      options_(options),
      scene_name_(s.name),
      sky_(s.sky),
      motion_(s.motion),
      // The tree is built first: the limits are checked with its exact size.
      host_arrays_(std::make_unique<gpu_scene::host_arrays>(gpu_scene::build(
          s, options.engine.use_bvh || options.engine.traversal != gpu_traversal::compute))),
      scene_buffers_(gpu_scene::buffers(ctx, *host_arrays_)),
      wg_(workgroup_size(ctx.device())),
      // The limits before any allocation, with the smallest targets: larger ones are checked
      // when asked for.
      scene_(
          (check_device_fits(ctx, render_targets::buffers(scene_buffers_, 1), "--scene " + s.name),
           std::make_unique<gpu_scene>(ctx, *host_arrays_))),
      targets_(std::make_unique<render_targets>(ctx, 1)),
      cache_(ctx, options.pipeline_cache_folder),
      timer_(ctx),
      exponent_(rtvk::sum_exponent(brightest(s.sky))),
      pacer_(pacing_of(ctx.device()), options.samples_per_dispatch, options.samples_per_submission,
             options.loop_budget) {
  const bool pipelines = options.engine.traversal == gpu_traversal::ray_pipeline;
  if (pipelines) render_stages_ |= VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR;
  upload();
  if (options.engine.traversal != gpu_traversal::compute) {
    const char* flag = pipelines ? "--accel rt-pipeline" : "--accel rt-query";
    if (pipelines ? !ctx.ray_tracing_pipelines() : !ctx.ray_queries()) {
      const std::string missing = missing_ray_tracing(ctx.device(), pipelines);
      throw usage_error(std::string(flag) + ": device '" + ctx.device().name + "' lacks " +
                        (missing.empty() ? std::string("it (not enabled)") : missing));
    }
    accel_ = std::make_unique<scene_accel>(ctx, *host_arrays_, s.motion,
                                           std::string(flag) + " --scene " + s.name);
  }
  host_arrays_.reset();  // on the device now
  if (pipelines) ray_times_ = make_ray_times(ctx_, targets_->pixels);
  trace_cost_ = options.trace_cost ? options.trace_cost : first_trace_cost;
  simulated_cuts_ = options.simulated_cuts;
  setup_seconds_ = seconds_since(start_);
}

void gpu_engine::upload() {
  ctx_.submit_and_wait([&](VkCommandBuffer cb) {
    scene_->record_upload(cb);
    barrier(cb, transfer_stage, VK_ACCESS_TRANSFER_WRITE_BIT, render_stages_,
            VK_ACCESS_SHADER_READ_BIT);
  });
}

render_targets& gpu_engine::targets_for(VkDeviceSize pixels) {
  if (targets_->pixels >= pixels) return *targets_;
  std::vector<buffer_request> wanted = render_targets::buffers(scene_buffers_, pixels);
  const bool times = options_.engine.traversal == gpu_traversal::ray_pipeline;
  if (times)
    wanted.push_back({"the rays' times", pixels * sizeof(float), true, memory_use::device_local});
  check_device_fits(ctx_, wanted, "--scene " + scene_name_);
  targets_.reset();  // no submission is in flight; the old ones go first to make room
  ray_times_.reset();
  thresholds_for_.reset();
  try {
    targets_ = std::make_unique<render_targets>(ctx_, pixels);
    if (times) ray_times_ = make_ray_times(ctx_, pixels);
  } catch (...) {  // the engine stays usable for smaller renders
    targets_ = std::make_unique<render_targets>(ctx_, 1);
    if (times) ray_times_ = make_ray_times(ctx_, 1);
    rebind_all();
    throw;
  }
  rebind_all();
  return *targets_;
}

void gpu_engine::rebind_all() {
  for (auto& [switches, pipeline] : pipelines_)
    pipeline->rebind(render_bindings(*scene_, *targets_, accel_.get(), ray_times_.get()));
  if (tonemap_) tonemap_->rebind(tonemap_bindings(*targets_));
}

const shader_program& gpu_engine::pipeline_for(bool jitter, bool lens, bool count_rays, bool lights,
                                               bool calibrated, bool nee) {
  const std::uint32_t switches = (jitter ? 1u : 0u) | (lens ? 2u : 0u) | (count_rays ? 4u : 0u) |
                                 (lights ? 8u : 0u) | (calibrated ? 16u : 0u) | (nee ? 32u : 0u);
  std::unique_ptr<shader_program>& p = pipelines_[switches];
  if (!p) {
    std::uint32_t spec[RTVK_SPEC_COUNT] = {};  // by constant_id
    spec[0] = wg_[0];
    spec[1] = wg_[1];
    spec[RTVK_SPEC_JITTER] = jitter;
    spec[RTVK_SPEC_LENS] = lens;
    spec[RTVK_SPEC_USE_BVH] = options_.engine.use_bvh;
    spec[RTVK_SPEC_COUNT_RAYS] = count_rays;
    scene_->specialize(spec);
    spec[RTVK_SPEC_LIGHTS] = lights;
    spec[RTVK_SPEC_CALIBRATED] = calibrated;
    spec[RTVK_SPEC_NEE] = nee;
    spec[RTVK_SPEC_STACK] = options_.stack_entries;
    const auto bindings = render_bindings(*scene_, *targets_, accel_.get(), ray_times_.get());
    switch (options_.engine.traversal) {
      case gpu_traversal::compute:
        p = std::make_unique<compute_pipeline>(ctx_, render_shader(), bindings, sizeof(render_push),
                                               spec, cache_.get());
        break;
      case gpu_traversal::ray_query:
        p = std::make_unique<compute_pipeline>(ctx_, render_query_shader(), bindings,
                                               sizeof(render_push), spec, cache_.get());
        break;
      case gpu_traversal::ray_pipeline:
        p = std::make_unique<ray_pipeline>(ctx_, render_ray_shaders(), bindings,
                                           sizeof(render_push), spec, cache_.get(), wg_);
        break;
    }
    cache_.save();  // a cache that cannot be written only makes the next run slower
  }
  return *p;
}

const compute_pipeline& gpu_engine::tonemap_pipeline() {
  if (!tonemap_) {
    tonemap_ = std::make_unique<compute_pipeline>(ctx_, tonemap_shader(),
                                                  tonemap_bindings(*targets_), sizeof(tonemap_push),
                                                  std::span<const std::uint32_t>{}, cache_.get());
    cache_.save();
  }
  return *tonemap_;
}

void gpu_engine::write_thresholds(const display_encoding& e) {
  tonemap_style_.transform = std::uint32_t(e.transform);
  tonemap_style_.mean_scale = float(std::exp2(e.exposure - exponent_));
  // AgX reads no thresholds; the others' tables depend on the curve, its gamma and exposure.
  if (!e.per_channel() || thresholds_for_ == e) return;
  const byte_thresholds t = make_byte_thresholds(e, exponent_);
  std::vector<uvec2> words(t.size());
  for (std::size_t k = 0; k < t.size(); ++k)
    words[k] = uvec2(std::uint32_t(t[k]), std::uint32_t(t[k] >> 32));
  ctx_.submit_and_wait([&](VkCommandBuffer cb) {  // nothing is in flight
    vkCmdUpdateBuffer(cb, targets_->thresholds.get(), 0, words.size() * sizeof(uvec2),
                      words.data());
    barrier(cb, transfer_stage, VK_ACCESS_TRANSFER_WRITE_BIT, compute_stage,
            VK_ACCESS_SHADER_READ_BIT);
  });
  thresholds_for_ = e;
}

std::vector<std::uint32_t> gpu_engine::encode_sums(const std::vector<pixel_sum>& sums,
                                                   const display_encoding& e) {
  if (sums.empty()) return {};
  render_targets& t = targets_for(sums.size());
  const compute_pipeline& tonemap = tonemap_pipeline();
  write_thresholds(e);
  const VkDeviceSize bytes = sums.size() * sizeof(pixel_sum);
  gpu_buffer staging(ctx_, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, memory_use::staging);
  staging.write(sums.data(), bytes);
  ctx_.submit_and_wait([&](VkCommandBuffer cb) {
    if (drawn_)
      barrier(cb, render_stages_ | transfer_stage,
              shader_rw | VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT,
              transfer_stage, VK_ACCESS_TRANSFER_WRITE_BIT);
    const VkBufferCopy in{0, 0, bytes};
    vkCmdCopyBuffer(cb, staging.get(), t.sums.get(), 1, &in);
    barrier(cb, transfer_stage, VK_ACCESS_TRANSFER_WRITE_BIT, compute_stage, shader_rw);
    record_tonemap(cb, tonemap, 0, sums.size(), ctx_.device(), tonemap_style_);
    barrier(cb, compute_stage, VK_ACCESS_SHADER_WRITE_BIT, transfer_stage,
            VK_ACCESS_TRANSFER_READ_BIT);
    const VkBufferCopy out{0, 0, sums.size() * 4};
    vkCmdCopyBuffer(cb, t.bytes.get(), t.readback.get(), 1, &out);
    barrier(cb, transfer_stage, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
            VK_ACCESS_HOST_READ_BIT);
  });
  drawn_ = true;
  const auto* rgba = static_cast<const std::uint32_t*>(t.readback.read());
  return std::vector<std::uint32_t>(rgba, rgba + sums.size());
}

void gpu_engine::draw(const std::vector<camera>& views, const render_settings& rs,
                      const render_window& win, readback_kind kind, const sample_progress& progress,
                      render_stats* stats, const band_sink& sink) {
  check_views(views, win);
  for (const camera& c : views) check_motion_span(motion_, scene_->moves(), c);
  const device_info& dev = ctx_.device();
  const bool kept = kind == readback_kind::kept;
  // Kept: the whole image's sums in one buffer, bands of any rows (accumulate checked the fit).
  const work_layout layout = kept ? work_layout{1, std::uint32_t(win.height)}
                                  : plan_work(dev, options_, win, views.size());
  render_targets& targets =
      kept ? targets_for(VkDeviceSize(win.width) * VkDeviceSize(views[0].image_height()))
           : targets_for(VkDeviceSize(win.width) * layout.band_rows * layout.views_per_group);
  // One 32-bit counter per pixel: it holds at most spp * max_depth rays. Read back with the sums
  // only (an encoded render reads back bytes); a kept render counts them in the status block.
  const bool count_rays =
      options_.engine.count_rays &&
      (kept || (kind == readback_kind::sums &&
                std::uint64_t(win.samples()) * std::uint64_t(rs.max_depth) < (1ull << 32)));
  const compute_pipeline* tonemap = nullptr;
  if (kind != readback_kind::sums) {
    tonemap = &tonemap_pipeline();
    write_thresholds(rs.encoding());
  }
  render_push push = make_push(sky_, rs, win, *scene_, exponent_);
  if (kept) push.sample_begin = 0;  // a kept pixel's count of samples is its next sample's index
  // The BVH's build is the first render's (after a replace_scene too): later ones reuse it.
  if (stats) *stats = render_stats{.build_seconds = built_drawn_ ? 0.0 : build_seconds()};
  built_drawn_ = true;
  const bool lens =
      std::any_of(views.begin(), views.end(), [](const camera& c) { return c.lens_radius() > 0; });
  const bool calibrated = std::any_of(views.begin(), views.end(), [](const camera& c) {
    return is_calibrated(c.projection()) || c.frame().readout != 0;
  });
  const bool nee = uses_nee(rs.sampling);
  band_commands commands(
      {ctx_, targets, timer_, wg_, drawn_, tonemap_style_},
      pipeline_for(rs.jitter, lens, count_rays, push.light_count > 0 && !nee, calibrated, nee),
      tonemap, push, std::uint32_t(win.width), kept, kept ? std::uint32_t(win.sample_begin) : 0);
  band_scheduler bands(commands, {pacer_, trace_cost_, simulated_cuts_}, win, push.sample_limit,
                       options_.engine.cancelled);
  draw_bands(views, win, layout, {commands, bands, targets, count_rays, kept}, progress, stats,
             sink);
}

void gpu_engine::draw_bands(const std::vector<camera>& views, const render_window& win,
                            const work_layout& layout, const band_tools& tools,
                            const sample_progress& progress, render_stats* stats,
                            const band_sink& sink) {
  // Bands as large as memory allows (layout) and the pacer's work allows now: a dispatch's work
  // is bounded by its pixels times its loop budget, so the first bands of a render on a device
  // not measured yet are small, and grow as the measured times allow.
  const VkDeviceSize width = VkDeviceSize(win.width), height = VkDeviceSize(win.height);
  band_pass b{};
  b.view_rows = views.size() * height;
  for (b.first_view = 0; b.first_view < views.size(); b.first_view += b.views) {
    const VkDeviceSize whole_views = pacer_.pixel_allowance() / (width * height);
    b.views = std::uint32_t(std::clamp<VkDeviceSize>(
        whole_views, 1,
        std::min<VkDeviceSize>(layout.views_per_group, views.size() - b.first_view)));
    tools.commands.set_views(views, b.first_view, b.views);
    for (std::uint32_t y = 0; y < std::uint32_t(win.height); y += b.rows) {
      b.rows = b.views > 1 ? std::uint32_t(win.height)
                           : std::uint32_t(std::clamp<VkDeviceSize>(
                                 pacer_.pixel_allowance() / width, 1,
                                 std::min<VkDeviceSize>(layout.band_rows, height - y)));
      b.y0 = std::uint32_t(win.y) + y;
      try {
        tools.bands.draw(b, progress, stats);
      } catch (...) {
        ctx_.wait_all();  // the other submission in flight still uses the targets
        throw;
      }
      b.view_rows_before += b.pixels();
      const render_status& st = tools.bands.last_status();  // the band's: all its samples' counts
      if (stats) {
        stats->dropped_samples += st.dropped_samples;
        stats->stack_overflows += st.stack_overflows;
      }
      if (tools.kept) {
        if (stats && tools.count_rays)
          stats->rays += std::uint64_t(st.rays_high) << 32 | st.rays_low;
        continue;
      }
      const void* data = tools.targets.readback.read();
      if (stats && tools.count_rays) {
        const auto* sums = static_cast<const pixel_sum*>(data);
        const std::size_t n = std::size_t(win.width) * b.pixels();
        for (std::size_t i = 0; i < n; ++i) stats->rays += sums[i].rays;
      }
      sink(b.first_view, b.views, int(b.y0) - win.y, int(b.rows), data);
    }
  }
}

bool gpu_engine::accumulation_fits(int width, int height) const {
  return VkDeviceSize(width) * VkDeviceSize(height) * sizeof(pixel_sum) <=
         ctx_.device().limits.maxStorageBufferRange;
}

void gpu_engine::reset_accumulation(int width, int height) {
  const VkDeviceSize pixels = VkDeviceSize(width) * VkDeviceSize(height);
  if (!accumulation_fits(width, height))
    throw usage_error("a " + std::to_string(width) + "x" + std::to_string(height) +
                      " accumulation needs " + format_bytes(pixels * sizeof(pixel_sum)) +
                      " of sums in one storage buffer; device '" + ctx_.device().name +
                      "' allows " + format_bytes(ctx_.device().limits.maxStorageBufferRange));
  const render_targets& t = targets_for(pixels);
  ctx_.submit_and_wait([&](VkCommandBuffer cb) {
    if (drawn_)
      barrier(cb, render_stages_ | transfer_stage, shader_rw | VK_ACCESS_TRANSFER_READ_BIT,
              transfer_stage, VK_ACCESS_TRANSFER_WRITE_BIT);
    vkCmdFillBuffer(cb, t.bytes.get(), 0, pixels * 4, 0xff000000u);
    barrier(cb, transfer_stage, VK_ACCESS_TRANSFER_WRITE_BIT, render_stages_ | transfer_stage,
            shader_rw | VK_ACCESS_TRANSFER_READ_BIT);
  });
}

void gpu_engine::accumulate(const camera& cam, const render_settings& rs, const render_window& win,
                            render_stats* stats) {
  if (win.x != 0 || win.width != cam.image_width())
    throw std::invalid_argument("accumulate: the window must span the image's width");
  if (!accumulation_fits(cam.image_width(), cam.image_height()) ||
      targets_->pixels < VkDeviceSize(cam.image_width()) * VkDeviceSize(cam.image_height()))
    reset_accumulation(cam.image_width(), cam.image_height());  // throws when it cannot fit
  draw({cam}, rs, win, readback_kind::kept, {}, stats, {});
}

image_rgb8 gpu_engine::read_accumulation(int width, int height) {
  const VkDeviceSize pixels = VkDeviceSize(width) * VkDeviceSize(height);
  if (targets_->pixels < pixels) throw std::invalid_argument("read_accumulation: no such image");
  ctx_.submit_and_wait([&](VkCommandBuffer cb) {
    barrier(cb, render_stages_ | transfer_stage,
            VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT, transfer_stage,
            VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT);
    const VkBufferCopy copy{0, 0, pixels * 4};
    vkCmdCopyBuffer(cb, targets_->bytes.get(), targets_->readback.get(), 1, &copy);
    barrier(cb, transfer_stage, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
            VK_ACCESS_HOST_READ_BIT);
  });
  return rgb_of_rgba(static_cast<const std::uint8_t*>(targets_->readback.read()), width, height);
}

std::vector<framebuffer> gpu_engine::render_views(const std::vector<camera>& views,
                                                  const render_settings& rs,
                                                  const render_window& win,
                                                  const sample_progress& progress,
                                                  render_stats* stats) {
  auto out = framebuffers_for(views.size(), win);
  draw(views, rs, win, readback_kind::sums, progress, stats, means_into(out, win.width, exponent_));
  return out;
}

std::vector<image_rgb8> gpu_engine::render_encoded(const std::vector<camera>& views,
                                                   const render_settings& rs,
                                                   const render_window& win,
                                                   const sample_progress& progress,
                                                   render_stats* stats) {
  auto out = images_for(views.size(), win);
  draw(views, rs, win, readback_kind::bytes, progress, stats, bytes_into(out, win.width));
  return out;
}

std::vector<sum_image> gpu_engine::render_sums(const std::vector<camera>& views,
                                               const render_settings& rs, const render_window& win,
                                               const sample_progress& progress,
                                               render_stats* stats) {
  auto out = sum_images_for(views.size(), win, exponent_);
  draw(views, rs, win, readback_kind::sums, progress, stats, sums_into(out, win.width));
  return out;
}

}  // namespace rtvk::gpu
