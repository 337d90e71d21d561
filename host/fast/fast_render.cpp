// The fast mode's pixel loop: host/cpu/render_cpu.cpp's, in float over the GPU's arrays. Each
// pixel's sample draws the numbers the GPU's and the reference's draw (pixel_sample_stream), so
// the three images differ only by the precision of the arithmetic.
#include <atomic>
#include <cmath>
#include <utility>

#include "camera_rays.h"
#include "fast_render.h"
#include "fast_shading.h"
#include "parallel.h"
// The host's own double arithmetic (the 8-bit encoding's sums): not the kernels', which
// -Wdouble-promotion guards here.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#include "render_settings.h"
#pragma GCC diagnostic pop

namespace rtvk {
namespace {

using namespace rtvk::fast;

// What every pixel of one render reads.
struct pixel_inputs {
  const fast::world& world;
  const shading_tables& tables;
  camera_frame camera;  // the camera buffer's fields, as get_ray reads them
  const fast_settings& settings;
  const render_window& win;
};

// A sample's color can be added where it is finite (NaN and infinities are dropped, as on the GPU).
bool finite_sample(real3 c) {
  return std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z);
}

// The mean of pixel (i, y)'s samples, y counted from the top.
glm::dvec3 pixel_color(const pixel_inputs& in, int i, int y, std::uint64_t& dropped,
                       std::uint64_t& rays) {
  const fast_settings& s = in.settings;
  const uint width = s.camera.image_width, height = s.camera.image_height;
  const uint j = height - 1u - uint(y);  // the lesson counts rows from the bottom
  glm::dvec3 sum(0);
  for (int sample = in.win.sample_begin; sample < in.win.sample_end; ++sample) {
    const random_stream hashed =
        pixel_sample_stream(s.seed, uint(y) * width + uint(i), uint(sample));
    const random_stream rnd = s.nee ? with_low_discrepancy(hashed) : hashed;
    const ray r = sample_ray(in.camera, width, height, uint(i), j, rnd, s.jitter, true,
                             s.sample_lights ? s.strata : 1u, uint(sample));
    const real3 c = fast::ray_color(r, in.world, in.tables, s.max_depth, rnd, rays);
    if (finite_sample(c))
      sum += glm::dvec3(c);
    else
      ++dropped;
  }
  return sum / double(in.win.sample_end - in.win.sample_begin);
}

camera_frame frame_of(const gpu::camera_ubo& u) {
  camera_frame f{};
#define RTVK_UNPACK_CAMERA_FIELD(type, name) f.name = u.name;
  RTVK_CAMERA_FIELDS(RTVK_UNPACK_CAMERA_FIELD)
#undef RTVK_UNPACK_CAMERA_FIELD
  return f;
}

}  // namespace

struct fast_scene::impl {
  impl(gpu::scene_arrays a, float motion_begin, float motion_end)
      : arrays(std::move(a)), world(arrays, motion_begin, motion_end) {}
  const gpu::scene_arrays arrays;  // the world points into them
  const fast::world world;
};

fast_scene::fast_scene(gpu::scene_arrays arrays, float motion_begin, float motion_end)
    : impl_(std::make_unique<impl>(std::move(arrays), motion_begin, motion_end)) {}

fast_scene::~fast_scene() = default;

framebuffer fast_scene::render(const fast_settings& settings, const render_window& win,
                               const std::function<void(int)>& progress,
                               const engine_options& engine, render_stats* stats) const {
  const shading_tables tables(impl_->arrays, settings);
  const pixel_inputs in{impl_->world, tables, frame_of(settings.camera), settings, win};
  framebuffer fb(win.width, win.height);
  const std::size_t width = std::size_t(win.width);
  std::atomic<std::uint64_t> dropped{0}, rays{0};
  parallel_pixels(win.width, win.height, engine.threads, engine.cancelled, progress,
                  [&](std::size_t begin, std::size_t end) {
                    std::uint64_t chunk_dropped = 0, chunk_rays = 0;
                    for (std::size_t p = begin; p < end; ++p) {
                      const int row = int(p / width), column = int(p % width);
                      fb.at(column, row) =
                          pixel_color(in, win.x + column, win.y + row, chunk_dropped, chunk_rays);
                    }
                    dropped += chunk_dropped;
                    rays += chunk_rays;
                  });
  if (stats) *stats = {.rays = rays.load(), .dropped_samples = dropped.load()};
  return fb;
}

}  // namespace rtvk
