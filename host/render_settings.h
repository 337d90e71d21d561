#pragma once
#include <cstdint>
#include <functional>

namespace rtvk {

// How to render a scene: what a scene file's "render" object holds, and what the CLI overrides.
struct render_settings {
  int width = 400;             // image width, pixels
  double aspect = 16.0 / 9.0;  // image width / height
  int spp = 1;                 // samples per pixel
  int max_depth = 50;          // most scatter events a path may take
  std::uint32_t seed = 0;      // random number seed: same seed, same image
  double gamma = 1;            // output encoding: 1 linear (the lesson), 2 the book's sqrt
  bool jitter = false;         // random sample positions inside each pixel (antialiasing)
};

// The part of a render that one run draws: a rectangle of the image and a range of each pixel's
// sample indices. Every pixel's random numbers depend only on (seed, pixel, sample, ...), so
// pieces drawn apart -- on other machines -- and merged equal the whole render.
struct render_window {
  int x = 0;             // left column, pixels from the image's left edge
  int y = 0;             // top row, pixels from the image's top edge
  int width = 0;         // pixels
  int height = 0;        // pixels
  int sample_begin = 0;  // first sample index drawn
  int sample_end = 0;    // one past the last sample index drawn

  int samples() const { return sample_end - sample_begin; }
  bool operator==(const render_window&) const = default;
};

// The whole image, every sample.
inline render_window whole_render(int image_width, int image_height, int spp) {
  return {0, 0, image_width, image_height, 0, spp};
}

// How a backend does the work, as opposed to what it draws: none of this changes the image.
struct engine_options {
  bool use_bvh = true;                // false: test every sphere for every ray (--accel none)
  int threads = 0;                    // CPU worker threads; 0: one per core
  std::uint32_t gpu_loop_budget = 0;  // GPU: most loop iterations per invocation; 0: the device's
  bool count_rays = false;            // fill render_stats::rays (costs a little on the GPU)
  std::uint64_t gpu_band_bytes = 0;   // GPU: largest accumulation buffer; 0: 64 MiB (or the
                                      // device's storage buffer limit, if smaller)
  // Polled between passes (a CPU row, a GPU submission); when it returns true the render stops
  // and throws render_cancelled. Empty: never cancelled.
  std::function<bool()> cancelled = {};
};

// What a render did, for `rtvk bench`.
struct render_stats {
  std::uint64_t rays = 0;    // rays traced: camera rays plus scattered rays
  double build_seconds = 0;  // of the render's time, building the BVH
  int submissions = 0;       // GPU: command buffers submitted (all views of a group share each)
};

inline constexpr int max_spp = 1 << 20;        // samples per pixel
inline constexpr int max_depth_limit = 10000;  // bounces

}  // namespace rtvk
