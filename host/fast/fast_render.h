#pragma once
// The CPU's fast mode: the scene's arrays (scene_arrays.h, the GPU's own floats) rendered on the
// CPU by the shared kernels compiled with float as `real`, packet_bvh and Embree finding the hits.
// Its images are the GPU's within the GPU's tolerances, at about the double-precision reference's
// speed on the books' scenes and 1.6x it on large meshes (docs/benchmarks.md). This header holds no
// kernel type: the reference's translation units (double kernels) include it to call in.
#include <cstdint>
#include <functional>
#include <memory>

#include "engine_options.h"
#include "framebuffer.h"
#include "scene_arrays.h"

namespace rtvk {

struct render_window;  // render_settings.h: the pixels and samples a render draws

// What a fast render reads besides the arrays, every value as the GPU's push constants and
// camera buffer hold it.
struct fast_settings {
  gpu::camera_ubo camera{};         // to_ubo of the render's camera
  glm::vec3 horizon{1}, zenith{1};  // the sky (scene::sky)
  std::uint32_t seed = 0;           // render_settings::seed
  std::uint32_t max_depth = 50;     // rays a path may trace
  std::uint32_t strata = 1;         // pixel_strata
  bool jitter = true;               // render_settings::jitter
  bool sample_lights = false;       // the third book's mixture aims at the lights
  bool nee = false;                 // next-event estimation
};

// A scene set up for fast renders: its arrays, and Embree's trees over them built once, with
// moving spheres bounded over [motion_begin, motion_end] (the scene's time span, seconds).
class fast_scene {
 public:
  fast_scene(gpu::scene_arrays arrays, float motion_begin, float motion_end);
  ~fast_scene();
  fast_scene(const fast_scene&) = delete;
  fast_scene& operator=(const fast_scene&) = delete;

  // The mean of the window's samples of each of its pixels, exactly as the whole render draws
  // them; rows shared out among engine.threads threads. `progress` (may be empty) gets the rows
  // done so far from the calling thread; engine.cancelled stops it with render_cancelled.
  // stats: the rays and dropped samples (build_seconds 0: the trees were built before).
  framebuffer render(const fast_settings& settings, const render_window& win,
                     const std::function<void(int)>& progress, const engine_options& engine,
                     render_stats* stats) const;

 private:
  struct impl;
  std::unique_ptr<impl> impl_;
};

}  // namespace rtvk
