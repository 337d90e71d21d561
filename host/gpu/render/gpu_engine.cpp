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

#include "compute_pipeline.h"
#include "elapsed.h"
#include "errors.h"
#include "format.h"
#include "gpu_scene.h"
#include "packing.h"
#include "parallel.h"
#include "ray_pipeline.h"
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

// One subgroup wide (so a row of pixels, whose paths start alike, shares a warp or a SIMD batch)
// and 64 invocations in all, within the device's limits: 8x8 on lavapipe (subgroups of 8),
// 32x2 on NVIDIA, 64x1 on AMD.
std::array<std::uint32_t, 2> workgroup_size(const device_info& d) {
  const VkPhysicalDeviceLimits& l = d.limits;
  const std::uint32_t total =
      std::min(std::max(64u, d.subgroup_size), l.maxComputeWorkGroupInvocations);
  const std::uint32_t x =
      std::max(1u, std::min({d.subgroup_size, l.maxComputeWorkGroupSize[0], total}));
  const std::uint32_t y = std::max(1u, std::min(total / x, l.maxComputeWorkGroupSize[1]));
  return {x, y};
}

void barrier(VkCommandBuffer cb, VkPipelineStageFlags src_stage, VkAccessFlags src,
             VkPipelineStageFlags dst_stage, VkAccessFlags dst) {
  VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  b.srcAccessMask = src;
  b.dstAccessMask = dst;
  vkCmdPipelineBarrier(cb, src_stage, dst_stage, 0, 1, &b, 0, nullptr, 0, nullptr);
}

constexpr VkPipelineStageFlags compute_stage = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
constexpr VkPipelineStageFlags transfer_stage = VK_PIPELINE_STAGE_TRANSFER_BIT;
constexpr VkAccessFlags shader_rw = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;

// The iterations each traced ray counts on the hardware paths, besides its candidates, for the
// driver's traversal loop rtvk cannot see (render_push::trace_cost): one at first, doubled
// whenever an invocation ran into a driver's loop limit (limit_was_hit) all the same. Mesa 25's
// lavapipe, the only one with the extensions, was not seen to cut a traversal even with budgets
// past its limit (tests/gpu/test_gpu_hardware_rt.cpp); the guard is there for drivers that do.
constexpr std::uint32_t first_trace_cost = 1;
constexpr std::uint32_t max_trace_cost = 1u << 14;

}  // namespace

namespace {

bool cpu_device(const device_info& dev) {
  return dev.type == VK_PHYSICAL_DEVICE_TYPE_CPU;
}

// How the views and rows of a render are grouped so that one group's sums fit one storage
// buffer (and a bounded share of device memory): many views of a small region at once, or one
// view in bands of whole rows when a single view is too large.
struct work_layout {
  std::uint32_t views_per_group;  // views one dispatch draws (its z size)
  std::uint32_t band_rows;        // rows of the region one dispatch draws
};

work_layout plan_work(const device_info& dev, const gpu_render_options& options,
                      const render_window& win, std::size_t views) {
  const VkDeviceSize row_bytes = VkDeviceSize(win.width) * sizeof(pixel_sum);
  const VkDeviceSize paced =
      pacing_for(cpu_device(dev)).small_bands && win.samples() >= 8
          ? std::max<VkDeviceSize>(1u << 15, (1u << 18) / VkDeviceSize(win.samples())) *
                sizeof(pixel_sum)
          : default_band_bytes;
  const VkDeviceSize limit = std::min<VkDeviceSize>(
      dev.limits.maxStorageBufferRange, options.band_bytes ? options.band_bytes : paced);
  const VkDeviceSize view_bytes = row_bytes * VkDeviceSize(win.height);
  if (view_bytes <= limit) {
    const VkDeviceSize fit = std::min<VkDeviceSize>(limit / view_bytes, RTVK_MAX_VIEWS);
    return {std::uint32_t(std::min<VkDeviceSize>(fit, views)), std::uint32_t(win.height)};
  }
  return {1, std::uint32_t(std::clamp<VkDeviceSize>(limit / row_bytes, 1, win.height))};
}

void check_views(const std::vector<camera>& views, const render_window& win) {
  if (views.empty()) throw std::invalid_argument("render_gpu_views: no views");
  for (const camera& c : views)
    if (c.image_width() != views[0].image_width() || c.image_height() != views[0].image_height())
      throw std::invalid_argument("render_gpu_views: views of different image sizes");
  check_window(win, views[0].image_width(), views[0].image_height());
}

// A sample needed more than the largest loop budget: the render fails rather than show it.
loop_budget_error overrun(const render_status& st, std::uint32_t budget, const device_info& dev) {
  return loop_budget_error(
      std::to_string(st.starved_pixels) + " pixel samples needed more than " +
      std::to_string(budget) + " loop iterations on " + dev.name +
      " (lavapipe silently stops loops at 65,535, so rtvk stops first, on every device, and "
      "writes no image): lower --depth, use fewer spheres or --sampling plain");
}

// Samples past the exact sums' limit: the render fails rather than clamp them into bias.
sample_overflow_error overflow(const render_status& st, float limit) {
  return sample_overflow_error(std::to_string(st.overflowed_samples) +
                               " samples had a channel above " + format_number(limit) +
                               ", more than rtvk's exact sums hold; no image was written");
}

// The brightest channel value the sums are scaled for: the sky's or the normal material's 1.
// Lamps and lights sampling's weights (at most twice the albedo a bounce) can go past it; a
// sample past the sums' limit (2^33 times this at most) fails the render rather than clamp.
double brightest(const sky& background) {
  double most = 1;
  for (int k = 0; k < 3; ++k) most = std::max({most, background.horizon[k], background.zenith[k]});
  return most;
}

// The push constants every dispatch of a render shares; the band and target fields are set for
// each pass.
render_push make_push(const sky& background, const render_settings& rs, const render_window& win,
                      const gpu_scene& objects, int exponent) {
  render_push push{};
  push.sky_horizon = vec3(background.horizon);
  push.sky_zenith = vec3(background.zenith);
  objects.set_counts(push);
  push.sample_begin = std::uint32_t(win.sample_begin);
  push.seed = rs.seed;
  push.max_depth = std::uint32_t(rs.max_depth);
  push.region_x0 = std::uint32_t(win.x);
  push.region_width = std::uint32_t(win.width);
  push.sum_scale = std::ldexp(1.0f, exponent);
  push.sample_limit = float(sum_sample_limit(exponent));
  // Lights sampling (the scene's lights were checked against the mode where it was asked for).
  const bool lights = samples_lights(objects.light_count(), rs.sampling);
  if (lights && (objects.light_count() == 0 || objects.light_count() > RTVK_MAX_LIGHTS))
    throw std::invalid_argument("--sampling lights: the scene has " +
                                std::to_string(objects.light_count()) + " lights to aim at");
  push.light_count = lights ? objects.light_count() : 0u;
  push.strata = pixel_strata(rs, lights);
  push.probe_trips = 2;  // limit_was_hit's loop (world_rt.glsl)
  return push;
}

// Every buffer the render shader reads or writes, by binding; on the hardware paths, the top
// level (`accel`) and, for a pipeline, the rays' times (`ray_times`) too.
std::vector<buffer_binding> render_bindings(const gpu_scene& g, const render_targets& t,
                                            const scene_accel* accel = nullptr,
                                            const gpu_buffer* ray_times = nullptr) {
  std::vector<buffer_binding> b = {
      {RTVK_BINDING_CAMERA, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, t.cameras.get()},
      {RTVK_BINDING_MATERIALS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, g.materials()},
      {RTVK_BINDING_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, t.sums.get()},
      {RTVK_BINDING_STATUS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, t.status.get()}};
  for (const buffer_binding& o : g.object_bindings()) b.push_back(o);
  for (const buffer_binding& o : g.appearance_bindings()) b.push_back(o);
  if (accel)
    b.push_back({RTVK_BINDING_TLAS, VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, VK_NULL_HANDLE,
                 accel->top()});
  if (ray_times)
    b.push_back({RTVK_BINDING_RAY_TIMES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, ray_times->get()});
  return b;
}

// What tonemap.comp reads and writes.
std::vector<buffer_binding> tonemap_bindings(const render_targets& t) {
  return {{RTVK_BINDING_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, t.sums.get()},
          {RTVK_BINDING_BYTES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, t.bytes.get()},
          {RTVK_BINDING_THRESHOLDS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, t.thresholds.get()}};
}

// tonemap.comp over `pixels` sums: 64 a workgroup, in rows of workgroups within the device's
// workgroup count limit (and tiles of those rows, by compute_pipeline::dispatch).
void record_tonemap(VkCommandBuffer cb, const compute_pipeline& tonemap, VkDeviceSize first,
                    VkDeviceSize pixels, const device_info& dev) {
  const VkDeviceSize groups = (pixels + 63) / 64;
  if (groups == 0) return;
  const VkDeviceSize row = std::min<VkDeviceSize>(groups, dev.limits.maxComputeWorkGroupCount[0]);
  tonemap.bind(cb);
  const tonemap_push tp{std::uint32_t(first), std::uint32_t(pixels), std::uint32_t(row * 64)};
  tonemap.push(cb, &tp, sizeof tp);
  tonemap.dispatch(cb, {std::uint32_t(row), std::uint32_t((groups + row - 1) / row), 1});
}

// One band: rows of a group of views, drawn with all their samples before the next. Where it is
// in the whole render, for progress and messages.
struct band_pass {
  std::size_t first_view;          // of the render's views
  std::uint32_t views;             // views in the group (the dispatch's z size)
  std::uint32_t y0, rows;          // image rows the band covers
  std::uint64_t view_rows_before;  // rows of all views drawn before this band
  std::uint64_t view_rows;         // rows of all views in the render
  VkDeviceSize pixels() const { return VkDeviceSize(views) * rows; }  // times the width
};

// What a band_renderer uses of its engine. `drawn` (some band was drawn before) and `pace` (the
// sizes of dispatches and submissions) carry over from one render to the next.
struct engine_parts {
  gpu_context& ctx;
  render_targets& targets;
  const device_timer& timer;
  std::array<std::uint32_t, 2> wg;  // workgroup size
  const gpu_render_options& options;
  bool& drawn;
  pacer& pace;
  std::uint32_t& trace_cost;      // render_push::trace_cost, doubled whenever a traversal was cut
  std::uint32_t& simulated_cuts;  // gpu_render_options::simulated_cuts still to make
};

// A submission in flight: what it asked of the pixels, and when.
struct in_flight {
  std::uint64_t ticket;                          // gpu_context::submit's
  std::uint32_t target;                          // samples every pixel has once it is done...
  bool complete;                                 // ...unless some are unfinished (final target)
  std::uint32_t dispatches;                      // it recorded
  std::chrono::steady_clock::time_point queued;  // when it was submitted
};

// Draws bands. Each submission brings every pixel up by `batch` samples, in dispatches of
// `per_dispatch` samples each; two submissions are in flight at once, so the device starts the
// next while the host waits for the last. Both sizes grow from one to what pacing_for asks of the
// device: on a GPU, submissions of about a tenth of a second (long enough to keep the device
// busy, short enough for progress, interruption and the fence timeout) and dispatches of a few
// milliseconds of device time. Pixels whose loop budget ran out go on in the next dispatch; once
// the last target is asked for, the renderer waits, and submits again until no pixel is unfinished.
// The last submission of a band ends with its readback (sums, or bytes encoded by
// tonemap_pipeline). A band `kept` on the device (the viewer's accumulation) goes on from the
// sums the image's buffer holds for its rows (every pixel at `target_base` samples; cleared
// first when that is 0), and ends with those rows encoded into the image's bytes, not read back.
class band_renderer {
 public:
  band_renderer(const engine_parts& engine, const shader_program& pipeline,
                const compute_pipeline* tonemap, const render_push& push, const render_window& win,
                bool kept)
      : e_(engine),
        pipeline_(pipeline),
        tonemap_(tonemap),
        push_(push),
        win_(win),
        kept_(kept),
        target_base_(kept ? std::uint32_t(win.sample_begin) : 0),
        compute_stage(VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | pipeline.stages()) {}

  // The cameras of the views the next bands draw (written into the command stream).
  void set_views(const std::vector<camera>& views, std::size_t first, std::uint32_t count) {
    cameras_.resize(count);
    for (std::uint32_t v = 0; v < count; ++v) cameras_[v] = to_ubo(views[first + v]);
  }

  // Every sample of the band; `progress` is called with samples done over all passes.
  void draw(const band_pass& b, const sample_progress& progress, render_stats* stats) {
    push_.band_y0 = b.y0;
    push_.band_rows = b.rows;
    push_.sums_row0 = kept_ ? b.y0 : 0;
    const std::uint32_t samples = std::uint32_t(win_.samples());
    std::deque<in_flight> pending;
    std::uint32_t target = 0;        // asked of every pixel so far
    std::uint32_t final_passes = 0;  // completed submissions asking for the last target
    bool first = true;
    // Each pass at the last target moves every unfinished pixel on by a sample at least, unless
    // the pixel starved and the budget grows (a few times at most): more passes than that would
    // mean none moves any more.
    const std::uint32_t most_final_passes = samples + 16;
    cuts_seen_ = 0;  // the band's status is cleared
    for (;;) {
      if (e_.options.engine.cancelled && e_.options.engine.cancelled()) {
        e_.ctx.wait_all();
        throw cancelled(b, target);
      }
      const std::uint32_t from = target;
      target = std::min(samples, target + e_.pace.samples_per_submission());
      pending.push_back(submit(b, first, from, target, target == samples));
      first = false;
      // Wait for the oldest while the newest runs; at the last target, for all of them.
      while (!pending.empty() &&
             (pending.size() == gpu_context::submission_slots || target == samples)) {
        const in_flight done = pending.front();
        pending.pop_front();
        finish(done, stats);
        if (progress) progress(progress_value(b, done.target));
        if (done.complete && unfinished() == 0) return;
        if (done.complete && ++final_passes > most_final_passes)
          throw std::runtime_error(
              "the GPU render stopped advancing: " + std::to_string(unfinished()) +
              " pixels still unfinished after " + std::to_string(final_passes) + " passes on " +
              e_.ctx.device().name);
      }
    }
  }

 private:
  render_cancelled cancelled(const band_pass& b, std::uint32_t done) const {
    return render_cancelled(
        "stopped after " + std::to_string(done) + " of " + std::to_string(win_.samples()) +
        " samples per pixel of rows " + std::to_string(b.y0) + " to " +
        std::to_string(b.y0 + b.rows - 1) + " of view " + std::to_string(b.first_view + 1) +
        (b.views > 1 ? " to " + std::to_string(b.first_view + b.views) : std::string()) + " of " +
        std::to_string(b.view_rows / std::uint64_t(win_.height)));
  }

  // Samples per pixel of the whole render done, as if every pixel had the same share.
  int progress_value(const band_pass& b, std::uint32_t target) const {
    const std::uint64_t done =
        b.view_rows_before * std::uint64_t(win_.samples()) + std::uint64_t(b.pixels()) * target;
    return int(done / b.view_rows);
  }

  std::uint32_t unfinished() {
    return static_cast<const render_status*>(e_.targets.status_readback.read())->unfinished_pixels;
  }

  in_flight submit(const band_pass& b, bool first, std::uint32_t from, std::uint32_t to,
                   bool last) {
    const std::uint32_t step = e_.pace.samples_per_dispatch();
    push_.loop_budget = e_.pace.loop_budget(VkDeviceSize(win_.width) * b.pixels());
    push_.trace_cost = e_.trace_cost;
    push_.probe_trips = 2;
    if (e_.simulated_cuts > 0) {
      --e_.simulated_cuts;
      push_.probe_trips = 3;  // limit_was_hit: a 3-trip loop is not the 2-trip one it expects
    }
    std::uint32_t dispatches = 0;
    const std::uint64_t ticket = e_.ctx.submit(
        [&](VkCommandBuffer cb) { dispatches = record(cb, b, first, from, to, step, last); });
    e_.drawn = true;
    return {ticket, to, last, dispatches, std::chrono::steady_clock::now()};
  }

  // After the submission is done: device time, overruns, and the sizes of the next ones.
  void finish(const in_flight& f, render_stats* stats) {
    e_.ctx.wait(f.ticket);
    const double device_seconds = e_.timer.seconds(f.ticket);
    const double wall = seconds_since(f.queued);
    if (stats) {
      ++stats->submissions;
      stats->gpu_seconds += device_seconds;
    }
    // A sample that did not fit its budget is drawn again under a larger one; one that did not
    // fit the largest fails the render.
    const auto& st = *static_cast<const render_status*>(e_.targets.status_readback.read());
    if (st.starved_pixels > 0 && !e_.pace.starved(st.starved_budget))
      throw overrun(st, st.starved_budget, e_.ctx.device());
    // The driver's loop limit cut some traversal short: those pixels kept nothing of it and go
    // on in the next pass, where each ray counts twice as many iterations.
    // (The band's status counts them since its start: only the new ones count here.)
    if (st.cut_traversals > cuts_seen_) {
      e_.trace_cost = std::min(e_.trace_cost * 2, max_trace_cost);
      if (stats) stats->cut_traversals += st.cut_traversals - cuts_seen_;
      cuts_seen_ = st.cut_traversals;
    }
    if (st.overflowed_samples > 0) throw overflow(st, push_.sample_limit);
    // Device time where there is a timer: the wall time includes waiting behind the other
    // submission in flight.
    e_.pace.measured(e_.timer.available() ? device_seconds : wall, f.dispatches);
  }

  // Before a band's first samples: cleared sums and status.
  void record_start(VkCommandBuffer cb) const {
    if (e_.drawn) {  // the previous band's shader writes and copies out of these buffers come first
      barrier(cb, compute_stage | transfer_stage,
              shader_rw | VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT,
              transfer_stage, VK_ACCESS_TRANSFER_WRITE_BIT);
    }
    // The group's cameras, in the command stream (no host-visible memory for the shader to
    // read; 16 KiB at most, within vkCmdUpdateBuffer's 64 KiB).
    vkCmdUpdateBuffer(cb, e_.targets.cameras.get(), 0, cameras_.size() * sizeof(camera_ubo),
                      cameras_.data());
    // Cleared for every band: a starved count is the band's to act on (the budget it raised
    // carries over in the pacer).
    vkCmdFillBuffer(cb, e_.targets.status.get(), 0, VK_WHOLE_SIZE, 0);
    if (!kept_) {
      vkCmdFillBuffer(cb, e_.targets.sums.get(), 0, VK_WHOLE_SIZE, 0);
    } else if (target_base_ == 0) {  // the band's rows of the image start afresh
      const VkDeviceSize row_bytes = VkDeviceSize(win_.width) * sizeof(pixel_sum);
      vkCmdFillBuffer(cb, e_.targets.sums.get(), push_.band_y0 * row_bytes,
                      push_.band_rows * row_bytes, 0);
    }
    barrier(cb, transfer_stage, VK_ACCESS_TRANSFER_WRITE_BIT, compute_stage,
            shader_rw | VK_ACCESS_UNIFORM_READ_BIT);
  }

  // After a band's last samples: the sums, or the bytes tonemap.comp makes of them, copied to
  // host-visible memory.
  void record_readback(VkCommandBuffer cb, const band_pass& b) const {
    const VkDeviceSize pixels = VkDeviceSize(win_.width) * b.pixels();
    barrier(cb, compute_stage, VK_ACCESS_SHADER_WRITE_BIT, compute_stage | transfer_stage,
            VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT);
    if (kept_) {  // encoded into the image's bytes, which stay for the viewer to show
      record_tonemap(cb, *tonemap_, VkDeviceSize(win_.width) * b.y0, pixels, e_.ctx.device());
      barrier(cb, compute_stage, VK_ACCESS_SHADER_WRITE_BIT, compute_stage | transfer_stage,
              VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT);
      return;
    }
    VkBufferCopy copy{0, 0, pixels * sizeof(pixel_sum)};
    VkBuffer from = e_.targets.sums.get();
    if (tonemap_) {
      record_tonemap(cb, *tonemap_, 0, pixels, e_.ctx.device());
      barrier(cb, compute_stage, VK_ACCESS_SHADER_WRITE_BIT, transfer_stage,
              VK_ACCESS_TRANSFER_READ_BIT);
      copy.size = pixels * 4;
      from = e_.targets.bytes.get();
    }
    vkCmdCopyBuffer(cb, from, e_.targets.readback.get(), 1, &copy);
    barrier(cb, transfer_stage, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
            VK_ACCESS_HOST_READ_BIT);
  }

  // One submission: dispatches bringing every pixel from `from` up to `to` samples, `step` at a
  // time. When `to` is the band's last target, the unfinished count is cleared before the last
  // dispatch (so it counts only that one) and the readback follows.
  // Returns the dispatches recorded.
  std::uint32_t record(VkCommandBuffer cb, const band_pass& b, bool first, std::uint32_t from,
                       std::uint32_t to, std::uint32_t step, bool last) {
    const std::uint64_t ticket = e_.ctx.next_ticket();
    e_.timer.record_begin(cb, ticket);
    if (first) {
      record_start(cb);
    } else {  // the previous submission's samples are in the sums this one adds to (and a
              // catch-up pass copies into the readback again)
      barrier(
          cb, compute_stage | transfer_stage,
          VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT,
          compute_stage | transfer_stage, shader_rw | VK_ACCESS_TRANSFER_WRITE_BIT);
    }
    std::uint32_t t = from;
    std::uint32_t dispatches = 0;
    bool first_dispatch = true;
    do {
      t = std::min(to, t + step);
      if (!first_dispatch)  // it goes on from the sums the one before left
        barrier(cb, compute_stage, VK_ACCESS_SHADER_WRITE_BIT, compute_stage, shader_rw);
      first_dispatch = false;
      if (last && t == to) {
        barrier(cb, compute_stage, shader_rw, transfer_stage, VK_ACCESS_TRANSFER_WRITE_BIT);
        vkCmdFillBuffer(cb, e_.targets.status.get(), offsetof(render_status, unfinished_pixels),
                        sizeof(std::uint32_t), 0);
        barrier(cb, transfer_stage, VK_ACCESS_TRANSFER_WRITE_BIT, compute_stage, shader_rw);
      }
      pipeline_.bind(cb);
      push_.sample_target = target_base_ + t;
      pipeline_.push(cb, &push_, sizeof push_);
      dispatches += pipeline_.dispatch(cb, {(push_.region_width + e_.wg[0] - 1) / e_.wg[0],
                                            (push_.band_rows + e_.wg[1] - 1) / e_.wg[1], b.views});
    } while (t < to);
    if (last) record_readback(cb, b);
    // The status the shader counted on the device, copied out for finish() to read.
    barrier(cb, compute_stage | transfer_stage,
            VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT, transfer_stage,
            VK_ACCESS_TRANSFER_READ_BIT);
    const VkBufferCopy status{0, 0, sizeof(render_status)};
    vkCmdCopyBuffer(cb, e_.targets.status.get(), e_.targets.status_readback.get(), 1, &status);
    barrier(cb, compute_stage | transfer_stage,
            VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
            VK_ACCESS_HOST_READ_BIT);
    e_.timer.record_end(cb, ticket);
    return dispatches;
  }

  engine_parts e_;  // the engine's context, targets, timer, options and carried-over state
  const shader_program& pipeline_;
  const compute_pipeline* tonemap_;  // encodes the readback to bytes; null: sums
  render_push push_;                 // band and target fields change per dispatch
  const render_window& win_;         // region and sample range of every view
  std::vector<camera_ubo> cameras_;  // of the views the bands draw (set_views)
  bool kept_;                        // the image's sums stay on the device (the viewer's)
  std::uint32_t target_base_;        // samples the kept sums already hold; 0 otherwise
  // The stages the render's shaders run in: compute (tonemap.comp, and render.comp or
  // render_query.comp) and the ray-tracing pipeline's, for barriers.
  VkPipelineStageFlags compute_stage;
  std::uint32_t cuts_seen_ = 0;  // render_status::cut_traversals of the band, as last read
};

// Runs body(row) for rows [0, rows) on every core: readback conversion should not leave all but
// one idle.
void for_rows(int rows, const std::function<void(int row)>& body) {
  parallel_for(std::size_t(std::max(rows, 0)), 0, 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t row = begin; row < end; ++row) body(int(row));
  });
}

// One image per view, each made in place: filling a vector with copies of one made first wrote
// every image twice (an H200 renders book-final's 1200x675 in 6 ms of device time, and copying
// its 19 MB framebuffer, page faults and all, cost about as much again).
template <typename Make>
auto one_per_view(std::size_t views, Make make) {
  std::vector<decltype(make())> out;
  out.reserve(views);
  for (std::size_t k = 0; k < views; ++k) out.push_back(make());
  return out;
}

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
           gpu_scene(ctx, *host_arrays_))),
      targets_(std::make_unique<render_targets>(ctx, 1)),
      cache_(ctx, options.pipeline_cache_folder),
      timer_(ctx),
      exponent_(rtvk::sum_exponent(brightest(s.sky))),
      pacer_(pacing_for(cpu_device(ctx.device())), options.samples_per_dispatch,
             options.samples_per_submission, options.loop_budget) {
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

const char* gpu_engine::traversal_name() const {
  switch (options_.engine.traversal) {
    case gpu_traversal::ray_query:
      return "rt-query";
    case gpu_traversal::ray_pipeline:
      return "rt-pipeline";
    case gpu_traversal::compute:
      break;
  }
  return options_.engine.use_bvh ? "bvh" : "none";
}

void gpu_engine::upload() {
  ctx_.submit_and_wait([&](VkCommandBuffer cb) {
    scene_.record_upload(cb);
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
  thresholds_gamma_ = 0;
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
    pipeline->rebind(render_bindings(scene_, *targets_, accel_.get(), ray_times_.get()));
  if (tonemap_) tonemap_->rebind(tonemap_bindings(*targets_));
}

const shader_program& gpu_engine::pipeline_for(bool jitter, bool lens, bool count_rays, bool lights,
                                               bool calibrated) {
  const std::uint32_t switches = (jitter ? 1u : 0u) | (lens ? 2u : 0u) | (count_rays ? 4u : 0u) |
                                 (lights ? 8u : 0u) | (calibrated ? 16u : 0u);
  std::unique_ptr<shader_program>& p = pipelines_[switches];
  if (!p) {
    std::uint32_t spec[RTVK_SPEC_COUNT] = {};  // by constant_id
    spec[0] = wg_[0];
    spec[1] = wg_[1];
    spec[RTVK_SPEC_JITTER] = jitter;
    spec[RTVK_SPEC_LENS] = lens;
    spec[RTVK_SPEC_USE_BVH] = options_.engine.use_bvh;
    spec[RTVK_SPEC_COUNT_RAYS] = count_rays;
    scene_.specialize(spec);
    spec[RTVK_SPEC_LIGHTS] = lights;
    spec[RTVK_SPEC_CALIBRATED] = calibrated;
    const auto bindings = render_bindings(scene_, *targets_, accel_.get(), ray_times_.get());
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

void gpu_engine::write_thresholds(double gamma) {
  if (thresholds_gamma_ == gamma) return;
  const byte_thresholds t = make_byte_thresholds(gamma, exponent_);
  std::vector<uvec2> words(t.size());
  for (std::size_t k = 0; k < t.size(); ++k)
    words[k] = uvec2(std::uint32_t(t[k]), std::uint32_t(t[k] >> 32));
  ctx_.submit_and_wait([&](VkCommandBuffer cb) {  // nothing is in flight
    vkCmdUpdateBuffer(cb, targets_->thresholds.get(), 0, words.size() * sizeof(uvec2),
                      words.data());
    barrier(cb, transfer_stage, VK_ACCESS_TRANSFER_WRITE_BIT, compute_stage,
            VK_ACCESS_SHADER_READ_BIT);
  });
  thresholds_gamma_ = gamma;
}

std::vector<std::uint32_t> gpu_engine::encode_sums(const std::vector<pixel_sum>& sums,
                                                   double gamma) {
  if (sums.empty()) return {};
  render_targets& t = targets_for(sums.size());
  const compute_pipeline& tonemap = tonemap_pipeline();
  write_thresholds(gamma);
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
    record_tonemap(cb, tonemap, 0, sums.size(), ctx_.device());
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
  for (const camera& c : views) check_motion_span(motion_, scene_.moves(), c);
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
    write_thresholds(rs.gamma);
  }
  render_push push = make_push(sky_, rs, win, scene_, exponent_);
  if (kept) push.sample_begin = 0;  // a kept pixel's count of samples is its next sample's index
  // The BVH's build is the first render's: later ones reuse it.
  if (stats) *stats = render_stats{.build_seconds = drawn_ ? 0.0 : build_seconds()};
  const bool lens =
      std::any_of(views.begin(), views.end(), [](const camera& c) { return c.lens_radius() > 0; });
  const bool calibrated = std::any_of(views.begin(), views.end(), [](const camera& c) {
    return is_calibrated(c.projection()) || c.frame().readout != 0;
  });
  band_renderer bands(
      {ctx_, targets, timer_, wg_, options_, drawn_, pacer_, trace_cost_, simulated_cuts_},
      pipeline_for(rs.jitter, lens, count_rays, push.light_count > 0, calibrated), tonemap, push,
      win, kept);

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
    bands.set_views(views, b.first_view, b.views);
    for (std::uint32_t y = 0; y < std::uint32_t(win.height); y += b.rows) {
      b.rows = b.views > 1 ? std::uint32_t(win.height)
                           : std::uint32_t(std::clamp<VkDeviceSize>(
                                 pacer_.pixel_allowance() / width, 1,
                                 std::min<VkDeviceSize>(layout.band_rows, height - y)));
      b.y0 = std::uint32_t(win.y) + y;
      try {
        bands.draw(b, progress, stats);
      } catch (...) {
        ctx_.wait_all();  // the other submission in flight still uses the targets
        throw;
      }
      b.view_rows_before += b.pixels();
      if (stats)  // the band's status holds its samples' count
        stats->dropped_samples +=
            static_cast<const render_status*>(targets.status_readback.read())->dropped_samples;
      if (kept) {
        if (stats && count_rays) {
          const auto& st = *static_cast<const render_status*>(targets.status_readback.read());
          stats->rays += std::uint64_t(st.rays_high) << 32 | st.rays_low;
        }
        continue;
      }
      const void* data = targets.readback.read();
      if (stats && count_rays) {
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
  const auto* rgba = static_cast<const std::uint8_t*>(targets_->readback.read());
  image_rgb8 out{width, height, std::vector<std::uint8_t>(std::size_t(pixels) * 3)};
  for (std::size_t i = 0; i < std::size_t(pixels); ++i)
    std::copy(rgba + 4 * i, rgba + 4 * i + 3, out.rgb.begin() + std::ptrdiff_t(3 * i));
  return out;
}

std::vector<framebuffer> gpu_engine::render_views(const std::vector<camera>& views,
                                                  const render_settings& rs,
                                                  const render_window& win,
                                                  const sample_progress& progress,
                                                  render_stats* stats) {
  auto out = one_per_view(views.size(), [&] { return framebuffer{win.width, win.height}; });
  const int f = exponent_;
  draw(views, rs, win, readback_kind::sums, progress, stats,
       [&](std::size_t first, std::uint32_t count, int row0, int rows, const void* data) {
         const auto* sums = static_cast<const pixel_sum*>(data);
         for_rows(int(count) * rows, [&](int r) {
           framebuffer& fb = out[first + std::size_t(r / rows)];
           const pixel_sum* p = sums + std::size_t(r) * std::size_t(win.width);
           const int y = row0 + r % rows;
           for (int x = 0; x < win.width; ++x, ++p)
             fb.at(x, y) =
                 color(sum_mean(red_sum(*p), p->samples, f), sum_mean(green_sum(*p), p->samples, f),
                       sum_mean(blue_sum(*p), p->samples, f));
         });
       });
  return out;
}

std::vector<image_rgb8> gpu_engine::render_encoded(const std::vector<camera>& views,
                                                   const render_settings& rs,
                                                   const render_window& win,
                                                   const sample_progress& progress,
                                                   render_stats* stats) {
  auto out = one_per_view(views.size(), [&] {
    return image_rgb8{
        win.width, win.height,
        std::vector<std::uint8_t>(std::size_t(win.width) * std::size_t(win.height) * 3)};
  });
  draw(views, rs, win, readback_kind::bytes, progress, stats,
       [&](std::size_t first, std::uint32_t count, int row0, int rows, const void* data) {
         const auto* rgba = static_cast<const std::uint8_t*>(data);
         for_rows(int(count) * rows, [&](int r) {
           image_rgb8& img = out[first + std::size_t(r / rows)];
           const std::uint8_t* from = rgba + std::size_t(r) * std::size_t(win.width) * 4;
           std::uint8_t* to = img.rgb.data() + std::size_t(row0 + r % rows) * win.width * 3;
           for (int x = 0; x < win.width; ++x, from += 4, to += 3) std::copy(from, from + 3, to);
         });
       });
  return out;
}

std::vector<sum_image> gpu_engine::render_sums(const std::vector<camera>& views,
                                               const render_settings& rs, const render_window& win,
                                               const sample_progress& progress,
                                               render_stats* stats) {
  auto out = one_per_view(views.size(), [&] {
    return sum_image{win.width, win.height, exponent_,
                     std::vector<pixel_sum>(std::size_t(win.width) * win.height)};
  });
  draw(views, rs, win, readback_kind::sums, progress, stats,
       [&](std::size_t first, std::uint32_t count, int row0, int rows, const void* data) {
         const auto* sums = static_cast<const pixel_sum*>(data);
         const std::size_t w = std::size_t(win.width);
         for (std::uint32_t v = 0; v < count; ++v)
           std::copy(sums + v * rows * w, sums + (v + 1) * rows * w,
                     out[first + v].pixels.begin() + std::ptrdiff_t(row0 * w));
       });
  return out;
}

}  // namespace rtvk::gpu
