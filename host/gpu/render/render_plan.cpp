#include "render_plan.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "light_sources.h"
#include "sample_sum.h"

namespace rtvk::gpu {

std::array<std::uint32_t, 2> workgroup_size(const device_info& d) {
  const VkPhysicalDeviceLimits& l = d.limits;
  const std::uint32_t total =
      std::min(std::max(64u, d.subgroup_size), l.maxComputeWorkGroupInvocations);
  const std::uint32_t x =
      std::max(1u, std::min({d.subgroup_size, l.maxComputeWorkGroupSize[0], total}));
  const std::uint32_t y = std::max(1u, std::min(total / x, l.maxComputeWorkGroupSize[1]));
  return {x, y};
}

bool cpu_device(const device_info& dev) {
  return dev.type == VK_PHYSICAL_DEVICE_TYPE_CPU;
}

bool loop_limited(const device_info& dev) {
  return dev.driver_id == VK_DRIVER_ID_MESA_LLVMPIPE;
}

pacing pacing_of(const device_info& dev) {
  return pacing_for(cpu_device(dev), loop_limited(dev));
}

work_layout plan_work(const device_info& dev, const gpu_render_options& options,
                      const render_window& win, std::size_t views) {
  const VkDeviceSize row_bytes = VkDeviceSize(win.width) * sizeof(pixel_sum);
  const VkDeviceSize paced =
      pacing_of(dev).small_bands && win.samples() >= 8
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

double brightest(const sky& background) {
  double most = 1;
  for (int k = 0; k < 3; ++k) most = std::max({most, background.horizon[k], background.zenith[k]});
  return most;
}

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
  // Next-event estimation draws the lamps through the light tree (any number): the count only says
  // whether there are some.
  const bool nee = uses_nee(rs.sampling);
  if (nee) push.light_count = objects.lamp_count();
  push.strata = pixel_strata(rs, lights);
  push.probe_trips = 2;  // limit_was_hit's loop (render_body.glsl)
  return push;
}

std::vector<buffer_binding> render_bindings(const gpu_scene& g, const render_targets& t,
                                            const scene_accel* accel, const gpu_buffer* ray_times) {
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

std::vector<buffer_binding> tonemap_bindings(const render_targets& t) {
  return {{RTVK_TONEMAP_SUMS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, t.sums.get()},
          {RTVK_TONEMAP_BYTES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, t.bytes.get()},
          {RTVK_TONEMAP_THRESHOLDS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, t.thresholds.get()}};
}

}  // namespace rtvk::gpu
