#include "gpu_engine.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <span>

#include "compute_pipeline.h"
#include "elapsed.h"
#include "errors.h"
#include "gpu_scene.h"
#include "packing.h"
#include "render_targets.h"
#include "shaders.h"

namespace rtvk::gpu {
namespace {

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

}  // namespace

namespace {

// How the views and rows of a render are grouped so that one group's sums fit one storage
// buffer (and a bounded share of device memory): many views of a small region at once, or one
// view in bands of whole rows when a single view is too large.
struct work_layout {
  std::uint32_t views_per_group;  // views one dispatch draws (its z size)
  std::uint32_t band_rows;        // rows of the region one dispatch draws
};

work_layout plan_work(const device_info& dev, const gpu_render_options& options,
                      const render_window& win, std::size_t views) {
  const VkDeviceSize row_bytes = VkDeviceSize(win.width) * 3 * sizeof(float);
  const VkDeviceSize limit =
      std::min<VkDeviceSize>(dev.limits.maxStorageBufferRange,
                             options.band_bytes ? options.band_bytes : default_band_bytes);
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

// Fails the render when any invocation ran out of its loop budget.
void check_overrun(const render_status& st, std::uint32_t budget, const device_info& dev) {
  if (st.overrun_pixels > 0)
    throw loop_budget_error(std::to_string(st.overrun_pixels) + " pixel samples needed more than " +
                            std::to_string(budget) + " loop iterations on " + dev.name +
                            " (lavapipe silently stops loops at 65,535, so rtvk stops first and "
                            "writes no image): lower --depth or use fewer spheres");
}

// The readback of one band -- for each view in turn, `rows` rows of sums -- divided into means
// and placed at row `first_row` of each view's framebuffer.
void unpack_band(const float* rgb, std::span<framebuffer> views, int first_row, int rows,
                 int samples) {
  for (framebuffer& fb : views)
    for (int row = first_row; row < first_row + rows; ++row)
      for (int x = 0; x < fb.width(); ++x, rgb += 3)
        fb.at(x, row) = divide(color(rgb[0], rgb[1], rgb[2]), samples);
}

// The push constants every dispatch of a render shares; the band and sample fields are set for
// each pass.
render_push make_push(const sky& background, const render_settings& rs, const render_window& win,
                      const gpu_render_options& options, const device_info& dev,
                      std::uint32_t sphere_count) {
  render_push push{};
  push.sky_horizon = vec3(background.horizon);
  push.sky_zenith = vec3(background.zenith);
  push.sphere_count = sphere_count;
  push.seed = rs.seed;
  push.max_depth = std::uint32_t(rs.max_depth);
  push.loop_budget = options.loop_budget ? options.loop_budget : default_loop_budget(dev);
  push.region_x0 = std::uint32_t(win.x);
  push.region_width = std::uint32_t(win.width);
  return push;
}

// Every buffer the render shader reads or writes, by binding.
std::vector<buffer_binding> bindings(const gpu_scene& g, const render_targets& t) {
  return {{RTVK_BINDING_CAMERA, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, t.cameras.get()},
          {RTVK_BINDING_SPHERES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, g.spheres()},
          {RTVK_BINDING_MATERIALS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, g.materials()},
          {RTVK_BINDING_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, t.image.get()},
          {RTVK_BINDING_STATUS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, t.status.get()},
          {RTVK_BINDING_BVH_NODES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, g.nodes()},
          {RTVK_BINDING_RAY_COUNT, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, t.ray_counts.get()}};
}

// Where one band is in the whole render, for progress and messages.
struct band_pass {
  std::size_t group, groups;  // view group, of how many
  std::uint32_t band, bands;  // band of the group, of how many
  std::uint32_t views;        // views in the group (the dispatch's z size)
  std::uint32_t y0, rows;     // image rows the band covers
};

// What a band_renderer uses of its engine. `drawn` (some band was drawn before) and `batch`
// (samples per submission) carry over from one render to the next.
struct engine_parts {
  gpu_context& ctx;
  render_targets& targets;
  const device_timer& timer;
  std::array<std::uint32_t, 2> wg;  // workgroup size
  const gpu_render_options& options;
  bool& drawn;
  int& batch;
};

// Draws bands: each in submissions of growing batches of samples that accumulate on the device,
// the last one copying the sums back. Submissions grow from one sample until each takes about a
// quarter second: long enough to keep the device busy, short enough for progress, interruption
// and the fence timeout.
class band_renderer {
 public:
  band_renderer(const engine_parts& engine, const compute_pipeline& pipeline,
                const render_push& push, const render_window& win, bool count_rays)
      : e_(engine), pipeline_(pipeline), push_(push), win_(win), count_rays_(count_rays) {}

  // Every sample of the band; `progress` is called with samples done over all passes.
  void draw(const band_pass& b, const sample_progress& progress, render_stats* stats) {
    push_.band_y0 = b.y0;
    push_.band_rows = b.rows;
    const int samples = win_.samples();
    const std::int64_t passes = std::int64_t(b.groups) * b.bands;
    int done = 0;
    while (done < samples) {
      if (e_.options.engine.cancelled && e_.options.engine.cancelled()) throw cancelled(b, done);
      const int count = std::min(e_.batch, samples - done);
      const auto start = std::chrono::steady_clock::now();
      e_.ctx.submit_and_wait(
          [&](VkCommandBuffer cb) { record(cb, b, done, count, done + count == samples); });
      e_.drawn = true;
      if (stats) {
        ++stats->submissions;
        stats->gpu_seconds += e_.timer.seconds();
      }
      check_overrun(*static_cast<const render_status*>(e_.targets.status.read()), push_.loop_budget,
                    e_.ctx.device());
      done += count;
      if (progress)
        progress(int((std::int64_t(b.group * b.bands + b.band) * samples + done) / passes));
      const double seconds = seconds_since(start);
      if (seconds < 0.25) e_.batch = std::min(e_.batch * 2, 256);
    }
  }

 private:
  render_cancelled cancelled(const band_pass& b, int done) const {
    return render_cancelled("stopped after " + std::to_string(done) + " of " +
                            std::to_string(win_.samples()) + " samples per pixel of band " +
                            std::to_string(b.band + 1) + " of " + std::to_string(b.bands) +
                            " of view group " + std::to_string(b.group + 1) + " of " +
                            std::to_string(b.groups));
  }

  // Before a band's first samples: cleared sums, and for a render's first band a cleared
  // overrun count.
  void record_start(VkCommandBuffer cb, bool first_band) const {
    if (e_.drawn) {  // the previous band's shader writes and copies out of these buffers come first
      barrier(cb, compute_stage | transfer_stage,
              VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT, transfer_stage,
              VK_ACCESS_TRANSFER_WRITE_BIT);
    }
    if (first_band) vkCmdFillBuffer(cb, e_.targets.status.get(), 0, VK_WHOLE_SIZE, 0);
    vkCmdFillBuffer(cb, e_.targets.image.get(), 0, VK_WHOLE_SIZE, 0);
    vkCmdFillBuffer(cb, e_.targets.ray_counts.get(), 0, VK_WHOLE_SIZE, 0);
    barrier(cb, transfer_stage, VK_ACCESS_TRANSFER_WRITE_BIT, compute_stage, shader_rw);
  }

  // After a band's last samples: the sums and ray counters copied to host-visible memory.
  void record_readback(VkCommandBuffer cb, std::uint32_t views) const {
    barrier(cb, compute_stage, VK_ACCESS_SHADER_WRITE_BIT, transfer_stage,
            VK_ACCESS_TRANSFER_READ_BIT);
    const VkDeviceSize pixels = VkDeviceSize(win_.width) * push_.band_rows * views;
    const VkBufferCopy copy{0, 0, pixels * 3 * sizeof(float)};
    vkCmdCopyBuffer(cb, e_.targets.image.get(), e_.targets.readback.get(), 1, &copy);
    const VkBufferCopy counts{0, 0, count_rays_ ? pixels * sizeof(std::uint32_t) : 4};
    vkCmdCopyBuffer(cb, e_.targets.ray_counts.get(), e_.targets.ray_readback.get(), 1, &counts);
    barrier(cb, transfer_stage, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
            VK_ACCESS_HOST_READ_BIT);
  }

  // One submission: `count` samples from sample `done` of the band, one dispatch each.
  void record(VkCommandBuffer cb, const band_pass& b, int done, int count, bool last) {
    e_.timer.record_begin(cb);
    if (done == 0) {
      record_start(cb, b.group == 0 && b.band == 0);
    } else {  // the previous submission's samples are in the sums this one adds to
      barrier(cb, compute_stage, VK_ACCESS_SHADER_WRITE_BIT, compute_stage, shader_rw);
    }
    pipeline_.bind(cb);
    for (int k = 0; k < count; ++k) {
      if (k > 0) barrier(cb, compute_stage, VK_ACCESS_SHADER_WRITE_BIT, compute_stage, shader_rw);
      push_.sample_index = std::uint32_t(win_.sample_begin + done + k);
      pipeline_.push(cb, &push_, sizeof push_);
      vkCmdDispatch(cb, (push_.region_width + e_.wg[0] - 1) / e_.wg[0],
                    (push_.band_rows + e_.wg[1] - 1) / e_.wg[1], b.views);
    }
    if (last) record_readback(cb, b.views);
    barrier(cb, compute_stage, VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
            VK_ACCESS_HOST_READ_BIT);
    e_.timer.record_end(cb);
  }

  engine_parts e_;  // the engine's context, targets, timer, options and carried-over state
  const compute_pipeline& pipeline_;
  render_push push_;          // band and sample fields change per pass
  const render_window& win_;  // region and sample range of every view
  bool count_rays_;           // the pixels' ray counters are read back
};

// A band's sums read back into each view's framebuffer, and its ray counts into the stats.
void read_band(render_targets& t, const band_pass& b, const render_window& win,
               std::span<framebuffer> views, bool count_rays, render_stats* stats) {
  if (stats && count_rays) {
    const auto* counts = static_cast<const std::uint32_t*>(t.ray_readback.read());
    const std::size_t n = std::size_t(win.width) * b.rows * b.views;
    for (std::size_t i = 0; i < n; ++i) stats->rays += counts[i];
  }
  unpack_band(static_cast<const float*>(t.readback.read()), views, int(b.y0) - win.y, int(b.rows),
              win.samples());
}

// The camera block for views [first, first + count).
void write_cameras(gpu_buffer& cameras, const std::vector<camera>& views, std::size_t first,
                   std::uint32_t count) {
  std::vector<camera_ubo> ubos(RTVK_MAX_VIEWS);
  for (std::uint32_t v = 0; v < count; ++v) ubos[v] = to_ubo(views[first + v]);
  cameras.write(ubos.data(), ubos.size() * sizeof(camera_ubo));  // no submission is in flight
}

}  // namespace

gpu_engine::gpu_engine(gpu_context& ctx, const scene& s, const gpu_render_options& options)
    : start_(std::chrono::steady_clock::now()),
      ctx_(ctx),
      options_(options),
      scene_name_(s.name),
      sky_(s.sky),
      scene_buffers_(gpu_scene::buffers(s, options.engine.use_bvh)),
      wg_(workgroup_size(ctx.device())),
      // The limits first, with the smallest targets: larger ones are checked when asked for.
      scene_((check_device_fits(ctx, render_targets::buffers(scene_buffers_, 12, 4),
                                "--scene " + s.name),
              gpu_scene(ctx, s, options.engine.use_bvh))),
      targets_(std::make_unique<render_targets>(ctx, 12, 4)),
      cache_(ctx, options.pipeline_cache_folder),
      timer_(ctx) {
  upload();
  setup_seconds_ = seconds_since(start_);
}

void gpu_engine::upload() {
  ctx_.submit_and_wait([&](VkCommandBuffer cb) {
    scene_.record_upload(cb);
    barrier(cb, transfer_stage, VK_ACCESS_TRANSFER_WRITE_BIT, compute_stage,
            VK_ACCESS_SHADER_READ_BIT);
  });
}

render_targets& gpu_engine::targets_for(VkDeviceSize image_bytes, VkDeviceSize count_bytes) {
  if (targets_->image.size() >= image_bytes && targets_->ray_counts.size() >= count_bytes)
    return *targets_;
  check_device_fits(ctx_, render_targets::buffers(scene_buffers_, image_bytes, count_bytes),
                    "--scene " + scene_name_);
  targets_.reset();  // no submission is in flight
  targets_ = std::make_unique<render_targets>(ctx_, image_bytes, count_bytes);
  for (auto& [switches, pipeline] : pipelines_) pipeline->rebind(bindings(scene_, *targets_));
  return *targets_;
}

const compute_pipeline& gpu_engine::pipeline_for(bool jitter, bool lens, bool count_rays) {
  const std::uint32_t switches = (jitter ? 1u : 0u) | (lens ? 2u : 0u) | (count_rays ? 4u : 0u);
  std::unique_ptr<compute_pipeline>& p = pipelines_[switches];
  if (!p) {
    std::uint32_t spec[6] = {};  // by constant_id
    spec[0] = wg_[0];
    spec[1] = wg_[1];
    spec[RTVK_SPEC_JITTER] = jitter;
    spec[RTVK_SPEC_LENS] = lens;
    spec[RTVK_SPEC_USE_BVH] = options_.engine.use_bvh;
    spec[RTVK_SPEC_COUNT_RAYS] = count_rays;
    p = std::make_unique<compute_pipeline>(ctx_, render_shader(), bindings(scene_, *targets_),
                                           sizeof(render_push), spec, cache_.get());
    cache_.save();  // a cache that cannot be written only makes the next run slower
  }
  return *p;
}

std::vector<framebuffer> gpu_engine::render_views(const std::vector<camera>& views,
                                                  const render_settings& rs,
                                                  const render_window& win,
                                                  const sample_progress& progress,
                                                  render_stats* stats) {
  check_views(views, win);
  const device_info& dev = ctx_.device();
  const work_layout layout = plan_work(dev, options_, win, views.size());
  const VkDeviceSize group_pixels =
      VkDeviceSize(win.width) * layout.band_rows * layout.views_per_group;
  // One 32-bit counter per pixel: it holds at most spp * max_depth rays.
  const bool count_rays = options_.engine.count_rays &&
                          std::uint64_t(win.samples()) * std::uint64_t(rs.max_depth) < (1ull << 32);
  render_targets& targets = targets_for(group_pixels * 3 * sizeof(float),
                                        count_rays ? group_pixels * sizeof(std::uint32_t) : 4);
  // The BVH's build is the first render's: later ones reuse it.
  if (stats) *stats = render_stats{.build_seconds = drawn_ ? 0.0 : build_seconds()};
  const bool lens =
      std::any_of(views.begin(), views.end(), [](const camera& c) { return c.lens_radius() > 0; });
  band_renderer bands({ctx_, targets, timer_, wg_, options_, drawn_, batch_},
                      pipeline_for(rs.jitter, lens, count_rays),
                      make_push(sky_, rs, win, options_, dev, scene_.sphere_count()), win,
                      count_rays);

  std::vector<framebuffer> out(views.size(), framebuffer{win.width, win.height});
  band_pass b{};
  b.bands = (std::uint32_t(win.height) + layout.band_rows - 1) / layout.band_rows;
  b.groups = (views.size() + layout.views_per_group - 1) / layout.views_per_group;
  for (b.group = 0; b.group < b.groups; ++b.group) {
    const std::size_t first_view = b.group * layout.views_per_group;
    b.views =
        std::uint32_t(std::min<std::size_t>(layout.views_per_group, views.size() - first_view));
    write_cameras(targets.cameras, views, first_view, b.views);
    for (b.band = 0; b.band < b.bands; ++b.band) {
      b.y0 = std::uint32_t(win.y) + b.band * layout.band_rows;
      b.rows = std::min(layout.band_rows, std::uint32_t(win.height) - b.band * layout.band_rows);
      bands.draw(b, progress, stats);
      read_band(targets, b, win, std::span(out).subspan(first_view, b.views), count_rays, stats);
    }
  }
  return out;
}

}  // namespace rtvk::gpu
