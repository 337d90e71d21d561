#pragma once
#include <functional>
#include <string>

#include "camera.h"
#include "cpu_scene.h"
#include "engine_options.h"
#include "framebuffer.h"
#include "render_settings.h"
#include "scene.h"

namespace rtvk {

// The lesson's main loop generalized to the book's: rows from the top, `spp` samples per pixel
// (jittered when asked), lens samples for depth of field. The framebuffer holds the mean linear
// color; gamma is applied when quantizing. Rows are shared out among `engine.threads` threads;
// every pixel's random numbers depend only on the pixel, so the image does not depend on them.
framebuffer render_cpu(const camera& cam, const scene& s, const render_settings& rs,
                       const progress_callback& progress = {}, const engine_options& engine = {},
                       render_stats* stats = nullptr);

// The same for part of the image and of the samples: the framebuffer is win.width x win.height
// and holds the mean of samples [win.sample_begin, win.sample_end) of those pixels, each computed
// exactly as the whole render computes it. Throws std::invalid_argument for a window outside the
// image or an empty sample range; rs.spp is not used.
framebuffer render_cpu_window(const camera& cam, const scene& s, const render_settings& rs,
                              const render_window& win, const progress_callback& progress = {},
                              const engine_options& engine = {}, render_stats* stats = nullptr);

// The number of worker threads `threads` asks for (0: one per core).
int worker_threads(int threads);

}  // namespace rtvk
