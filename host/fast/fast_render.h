#pragma once
// The CPU's fast mode: the scene's arrays (scene_arrays.h, the GPU's own floats) rendered on the
// CPU by the shared kernels compiled with float as `real`, Embree finding the hits. Its images
// are the GPU's within the GPU's tolerances, at several times the double-precision reference's
// speed (docs/benchmarks.md). This header holds no kernel type: the reference's translation
// units (double kernels) include it to call in.
#include <cstdint>
#include <functional>

#include "engine_options.h"
#include "framebuffer.h"
#include "scene_arrays.h"

namespace rtvk {

struct render_window;  // render_settings.h: the pixels and samples a render draws

// What a fast render reads besides the arrays, every value as the GPU's push constants and
// camera buffer hold it.
struct fast_settings {
  gpu::camera_ubo camera{};                // to_ubo of the render's camera
  glm::vec3 horizon{1}, zenith{1};         // the sky (scene::sky)
  std::uint32_t seed = 0;                  // render_settings::seed
  std::uint32_t max_depth = 50;            // rays a path may trace
  std::uint32_t strata = 1;                // pixel_strata
  bool jitter = true;                      // render_settings::jitter
  bool sample_lights = false;              // the third book's mixture aims at the lights
  bool nee = false;                        // next-event estimation
  float motion_begin = 0, motion_end = 0;  // the scene's time span, seconds
};

// The mean of the window's samples of each of its pixels, exactly as the whole render draws
// them; rows shared out among engine.threads threads. `progress` (may be empty) gets the rows done
// so far from the calling thread; engine.cancelled stops it with render_cancelled.
framebuffer render_fast_window(const gpu::scene_arrays& arrays, const fast_settings& settings,
                               const render_window& win, const std::function<void(int)>& progress,
                               const engine_options& engine, render_stats* stats);

}  // namespace rtvk
