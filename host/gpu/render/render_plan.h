#pragma once
// What a render asks of the device before any command is recorded: the workgroup size, how its
// views and rows are grouped into bands, the push constants every dispatch shares and the
// buffers its shaders are bound to.
#include <array>
#include <cstdint>
#include <vector>

#include "buffer.h"
#include "camera.h"
#include "context.h"
#include "descriptors.h"
#include "gpu_scene.h"
#include "pacer.h"
#include "render_gpu.h"
#include "render_settings.h"
#include "render_targets.h"
#include "scene.h"
#include "scene_accel.h"
#include "shared_types.h"

namespace rtvk::gpu {

// One subgroup wide (so a row of pixels, whose paths start alike, shares a warp or a SIMD batch)
// and 64 invocations in all, within the device's limits: 8x8 on lavapipe (subgroups of 8),
// 32x2 on NVIDIA, 64x1 on AMD.
std::array<std::uint32_t, 2> workgroup_size(const device_info& d);

// A CPU device (lavapipe): paced as one (pacing_for).
bool cpu_device(const device_info& dev);

// A driver known to stop an invocation's loops silently (lavapipe, by its driver ID,
// VK_DRIVER_ID_MESA_LLVMPIPE: never by its name, which a user may see renamed): its loop budgets
// stay below the limit (pacer.h's loop_limited_budget).
bool loop_limited(const device_info& dev);

// The pacing of a render on `dev`: its kind (cpu_device) and its loop limit (loop_limited).
pacing pacing_of(const device_info& dev);

// How the views and rows of a render are grouped so that one group's sums fit one storage
// buffer (and a bounded share of device memory): many views of a small region at once, or one
// view in bands of whole rows when a single view is too large.
struct work_layout {
  std::uint32_t views_per_group;  // views one dispatch draws (its z size)
  std::uint32_t band_rows;        // rows of the region one dispatch draws
};
work_layout plan_work(const device_info& dev, const gpu_render_options& options,
                      const render_window& win, std::size_t views);

// Throws std::invalid_argument unless there are views, all of one image size, and the window
// lies inside it.
void check_views(const std::vector<camera>& views, const render_window& win);

// The brightest channel value the sums are scaled for: the sky's or the normal material's 1.
// Lamps and lights sampling's weights (at most twice the albedo a bounce) can go past it; a
// sample past the sums' limit (2^33 times this at most) fails the render rather than clamp.
double brightest(const sky& background);

// The push constants every dispatch of a render shares; the band and target fields are set for
// each pass.
render_push make_push(const sky& background, const render_settings& rs, const render_window& win,
                      const gpu_scene& objects, int exponent);

// Every buffer the render shader reads or writes, by binding; on the hardware paths, the top
// level (`accel`) and, for a pipeline, the rays' times (`ray_times`) too.
std::vector<buffer_binding> render_bindings(const gpu_scene& g, const render_targets& t,
                                            const scene_accel* accel = nullptr,
                                            const gpu_buffer* ray_times = nullptr);
// What tonemap.comp reads and writes.
std::vector<buffer_binding> tonemap_bindings(const render_targets& t);

}  // namespace rtvk::gpu
