#include "render_gpu.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <span>

#include "buffer.h"
#include "bvh.h"
#include "compute_pipeline.h"
#include "device_fit.h"
#include "format.h"
#include "interrupt.h"
#include "packing.h"
#include "render_cpu.h"
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

// A storage buffer filled from host data through a staging copy recorded into `cb`.
template <typename T>
struct device_array {
  device_array(const gpu_context& ctx, std::vector<T> data)
      : count(data.size()),
        bytes((data.empty() ? 1 : data.size()) * sizeof(T)),
        staging(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, memory_use::upload),
        buffer(ctx, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
               memory_use::device_local) {
    if (data.empty()) data.resize(1);  // a buffer cannot be empty; `count` says 0
    staging.write(data.data(), bytes);
  }
  void record_upload(VkCommandBuffer cb) const {
    const VkBufferCopy copy{0, 0, bytes};
    vkCmdCopyBuffer(cb, staging.get(), buffer.get(), 1, &copy);
  }
  std::size_t count;   // elements the scene has
  VkDeviceSize bytes;  // buffer size
  gpu_buffer staging;  // host copy
  gpu_buffer buffer;   // what the shader reads
};

}  // namespace

std::uint32_t default_loop_budget(const device_info& d) {
  const bool llvmpipe = d.driver_name == "llvmpipe" || d.name.rfind("llvmpipe", 0) == 0;
  return llvmpipe ? 60'000u : 0xffffffffu;
}

namespace {

// How the views and rows of a render are grouped so that one group's sums fit one storage
// buffer (and a bounded share of device memory): many views of a small region at once, or one
// view in bands of whole rows when a single view is too large.
struct work_layout {
  std::uint32_t views_per_group;  // views one dispatch draws (its z size)
  std::uint32_t band_rows;        // rows of the region one dispatch draws
};

work_layout plan_work(const device_info& dev, const engine_options& engine,
                      const render_window& win, std::size_t views) {
  const VkDeviceSize row_bytes = VkDeviceSize(win.width) * 3 * sizeof(float);
  const VkDeviceSize limit = std::min<VkDeviceSize>(
      dev.limits.maxStorageBufferRange, engine.gpu_band_bytes ? engine.gpu_band_bytes : 64u << 20);
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

// Every buffer render_gpu_views allocates, in order, sized before anything is built: the BVH at
// its largest, 2N - 1 nodes for N spheres (a binary tree with at most N leaves).
std::vector<buffer_request> render_buffers(const scene& s, const engine_options& engine,
                                           VkDeviceSize image_bytes, VkDeviceSize count_bytes) {
  const VkDeviceSize n = s.spheres.size();
  const VkDeviceSize spheres = std::max<VkDeviceSize>(n, 1) * sizeof(gpu_sphere);
  const VkDeviceSize materials =
      std::max<VkDeviceSize>(s.materials.size(), 1) * sizeof(gpu_material);
  const bool tree = engine.use_bvh && n > 0;
  const VkDeviceSize nodes = (tree ? 2 * n - 1 : 1) * sizeof(bvh_node);
  const VkDeviceSize index = (tree ? n : 1) * sizeof(std::uint32_t);
  using u = memory_use;
  return {{"the camera block", RTVK_MAX_VIEWS * sizeof(camera_ubo), false, u::upload},
          {"the spheres' upload copy", spheres, false, u::upload},
          {"the sphere array", spheres, true, u::device_local},
          {"the materials' upload copy", materials, false, u::upload},
          {"the material array", materials, true, u::device_local},
          {"the BVH's upload copy", nodes, false, u::upload},
          {"the BVH", nodes, true, u::device_local},
          {"the BVH index's upload copy", index, false, u::upload},
          {"the BVH index", index, true, u::device_local},
          {"the ray counters", count_bytes, true, u::device_local},
          {"the ray counters' readback", count_bytes, false, u::readback},
          {"the image band", image_bytes, true, u::device_local},
          {"the image band's readback", image_bytes, false, u::readback},
          {"the status block", sizeof(render_status), true, u::readback}};
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

}  // namespace

framebuffer render_gpu(gpu_context& ctx, const camera& cam, const scene& s,
                       const render_settings& rs, const sample_progress& progress,
                       const engine_options& engine, render_stats* stats) {
  return std::move(render_gpu_views(ctx, {cam}, s, rs,
                                    whole_render(cam.image_width(), cam.image_height(), rs.spp),
                                    progress, engine, stats)
                       .front());
}

std::vector<framebuffer> render_gpu_views(gpu_context& ctx, const std::vector<camera>& views,
                                          const scene& s, const render_settings& rs,
                                          const render_window& win, const sample_progress& progress,
                                          const engine_options& engine, render_stats* stats) {
  check_views(views, win);
  const device_info& dev = ctx.device();
  const work_layout layout = plan_work(dev, engine, win, views.size());
  const VkDeviceSize group_pixels =
      VkDeviceSize(win.width) * layout.band_rows * layout.views_per_group;
  const VkDeviceSize image_bytes = group_pixels * 3 * sizeof(float);
  // One 32-bit counter per pixel: it holds at most spp * max_depth rays.
  const bool count_rays = engine.count_rays &&
                          std::uint64_t(win.samples()) * std::uint64_t(rs.max_depth) < (1ull << 32);
  const VkDeviceSize count_bytes = count_rays ? group_pixels * sizeof(std::uint32_t) : 4;
  check_device_fits(ctx, render_buffers(s, engine, image_bytes, count_bytes), "--scene " + s.name);

  gpu_buffer ubo_buf(ctx, RTVK_MAX_VIEWS * sizeof(camera_ubo), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                     memory_use::upload);
  const device_array<gpu_sphere> spheres(ctx, to_gpu_spheres(s));
  const device_array<gpu_material> materials(ctx, to_gpu_materials(s));
  const auto build_start = std::chrono::steady_clock::now();
  const bvh tree(engine.use_bvh ? s.spheres : std::vector<sphere>{});
  if (stats) {
    *stats = render_stats{};
    stats->build_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - build_start).count();
  }
  const device_array<bvh_node> nodes(ctx, tree.nodes());
  const device_array<std::uint32_t> bvh_index(ctx, tree.index());
  constexpr VkBufferUsageFlags storage_copy = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                              VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                              VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  gpu_buffer ray_counts(ctx, count_bytes, storage_copy, memory_use::device_local);
  gpu_buffer ray_readback(ctx, count_bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, memory_use::readback);
  gpu_buffer image(ctx, image_bytes, storage_copy, memory_use::device_local);
  gpu_buffer readback(ctx, image_bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, memory_use::readback);
  gpu_buffer status(ctx, sizeof(render_status),
                    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                    memory_use::readback);

  const auto wg = workgroup_size(dev);
  const compute_pipeline pipeline(
      ctx, render_shader(),
      {{RTVK_BINDING_CAMERA, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, ubo_buf.get()},
       {RTVK_BINDING_SPHERES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, spheres.buffer.get()},
       {RTVK_BINDING_MATERIALS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, materials.buffer.get()},
       {RTVK_BINDING_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, image.get()},
       {RTVK_BINDING_STATUS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, status.get()},
       {RTVK_BINDING_BVH_NODES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, nodes.buffer.get()},
       {RTVK_BINDING_BVH_INDEX, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, bvh_index.buffer.get()},
       {RTVK_BINDING_RAY_COUNT, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, ray_counts.get()}},
      sizeof(render_push), wg);

  render_push push{};
  push.sky_horizon = vec3(s.sky.horizon);
  push.sky_zenith = vec3(s.sky.zenith);
  push.sphere_count = std::uint32_t(spheres.count);
  push.seed = rs.seed;
  push.max_depth = std::uint32_t(rs.max_depth);
  push.loop_budget = engine.gpu_loop_budget ? engine.gpu_loop_budget : default_loop_budget(dev);
  push.jitter = rs.jitter ? 1u : 0u;
  push.use_bvh = engine.use_bvh ? 1u : 0u;
  push.count_rays = count_rays ? 1u : 0u;
  push.region_x0 = std::uint32_t(win.x);
  push.region_width = std::uint32_t(win.width);

  std::vector<framebuffer> out(views.size(), framebuffer{win.width, win.height});
  const int samples = win.samples();
  const std::uint32_t bands = (std::uint32_t(win.height) + layout.band_rows - 1) / layout.band_rows;
  const std::size_t groups = (views.size() + layout.views_per_group - 1) / layout.views_per_group;
  const std::int64_t passes = std::int64_t(groups) * bands;  // for progress
  bool uploaded = false;
  int batch = 1;
  for (std::size_t group = 0; group < groups; ++group) {
    const std::size_t first_view = group * layout.views_per_group;
    const std::uint32_t group_views =
        std::uint32_t(std::min<std::size_t>(layout.views_per_group, views.size() - first_view));
    std::vector<camera_ubo> ubos(RTVK_MAX_VIEWS);
    for (std::uint32_t v = 0; v < group_views; ++v) ubos[v] = to_ubo(views[first_view + v]);
    ubo_buf.write(ubos.data(), ubos.size() * sizeof(camera_ubo));  // no submission is in flight

    for (std::uint32_t band = 0; band < bands; ++band) {
      push.band_y0 = std::uint32_t(win.y) + band * layout.band_rows;
      push.band_rows =
          std::min(layout.band_rows, std::uint32_t(win.height) - band * layout.band_rows);
      // Submissions grow from one sample until each takes about a quarter second: long enough to
      // keep the device busy, short enough for progress, interruption and the fence timeout.
      int done = 0;
      while (done < samples) {
        if (engine.cancelled && engine.cancelled())
          throw render_cancelled("stopped after " + std::to_string(done) + " of " +
                                 std::to_string(samples) + " samples per pixel of band " +
                                 std::to_string(band + 1) + " of " + std::to_string(bands) +
                                 " of view group " + std::to_string(group + 1) + " of " +
                                 std::to_string(groups));
        const int count = std::min(batch, samples - done);
        const bool first = done == 0, last = done + count == samples;
        const auto start = std::chrono::steady_clock::now();
        ctx.submit_and_wait([&](VkCommandBuffer cb) {
          if (first) {
            if (!uploaded) {
              spheres.record_upload(cb);
              materials.record_upload(cb);
              nodes.record_upload(cb);
              bvh_index.record_upload(cb);
              vkCmdFillBuffer(cb, status.get(), 0, VK_WHOLE_SIZE, 0);
            } else {  // the previous band's copies out of these buffers come first
              barrier(cb, transfer_stage, VK_ACCESS_TRANSFER_READ_BIT, transfer_stage,
                      VK_ACCESS_TRANSFER_WRITE_BIT);
            }
            vkCmdFillBuffer(cb, image.get(), 0, VK_WHOLE_SIZE, 0);
            vkCmdFillBuffer(cb, ray_counts.get(), 0, VK_WHOLE_SIZE, 0);
            barrier(cb, transfer_stage, VK_ACCESS_TRANSFER_WRITE_BIT, compute_stage, shader_rw);
          } else {  // the previous submission's samples are in the sums this one adds to
            barrier(cb, compute_stage, VK_ACCESS_SHADER_WRITE_BIT, compute_stage, shader_rw);
          }
          pipeline.bind(cb);
          for (int k = 0; k < count; ++k) {
            if (k > 0)
              barrier(cb, compute_stage, VK_ACCESS_SHADER_WRITE_BIT, compute_stage, shader_rw);
            push.sample_index = std::uint32_t(win.sample_begin + done + k);
            pipeline.push(cb, &push, sizeof push);
            vkCmdDispatch(cb, (push.region_width + wg[0] - 1) / wg[0],
                          (push.band_rows + wg[1] - 1) / wg[1], group_views);
          }
          if (last) {
            barrier(cb, compute_stage, VK_ACCESS_SHADER_WRITE_BIT, transfer_stage,
                    VK_ACCESS_TRANSFER_READ_BIT);
            const VkDeviceSize pixels = VkDeviceSize(win.width) * push.band_rows * group_views;
            const VkBufferCopy copy{0, 0, pixels * 3 * sizeof(float)};
            vkCmdCopyBuffer(cb, image.get(), readback.get(), 1, &copy);
            const VkBufferCopy counts{0, 0, count_rays ? pixels * sizeof(std::uint32_t) : 4};
            vkCmdCopyBuffer(cb, ray_counts.get(), ray_readback.get(), 1, &counts);
            barrier(cb, transfer_stage, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                    VK_ACCESS_HOST_READ_BIT);
          }
          barrier(cb, compute_stage, VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                  VK_ACCESS_HOST_READ_BIT);
        });
        uploaded = true;
        if (stats) ++stats->submissions;
        check_overrun(*static_cast<const render_status*>(status.read()), push.loop_budget, dev);
        done += count;
        if (progress) progress(int((std::int64_t(group * bands + band) * samples + done) / passes));
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (seconds < 0.25) batch = std::min(batch * 2, 256);
      }

      const std::size_t band_pixels = std::size_t(win.width) * push.band_rows;
      if (stats && count_rays) {
        const auto* counts = static_cast<const std::uint32_t*>(ray_readback.read());
        for (std::size_t i = 0; i < band_pixels * group_views; ++i) stats->rays += counts[i];
      }
      unpack_band(static_cast<const float*>(readback.read()),
                  std::span(out).subspan(first_view, group_views), int(push.band_y0) - win.y,
                  int(push.band_rows), samples);
    }
  }
  return out;
}

}  // namespace rtvk::gpu
