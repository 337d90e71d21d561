#pragma once
#include <cstdint>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <vector>

#include "camera.h"
#include "context.h"
#include "engine_options.h"
#include "framebuffer.h"
#include "render_settings.h"
#include "scene.h"

namespace rtvk::gpu {

// A dispatch ran out of its loop budget: some pixels' samples were not computed.
class loop_budget_error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A sample had a channel past the exact sums' limit (sum_sample_limit, sample_sum.h): the
// render fails rather than clamp it into a biased image.
class sample_overflow_error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The largest accumulation buffer a render allocates unless told otherwise (or the device's
// storage buffer limit, if smaller), bytes.
inline constexpr std::uint64_t default_band_bytes = 64u << 20;

// How the GPU does the work: the backend-neutral options plus what only the GPU has.
struct gpu_render_options {
  engine_options engine = {};     // BVH or not, ray counting, cancellation
  std::uint32_t loop_budget = 0;  // loop iterations per invocation, fixed; 0: paced (pacer.h)
  std::uint64_t band_bytes = 0;   // largest accumulation buffer; 0: default_band_bytes
  // Samples per dispatch and per submission; 0: adapted to the measured times (tests fix them).
  std::uint32_t samples_per_dispatch = 0;
  std::uint32_t samples_per_submission = 0;
  // The hardware paths' first render_push::trace_cost; 0: the device's default (tests lower it
  // to make lavapipe's loop limit cut traversals short).
  std::uint32_t trace_cost = 0;
  // Tests only: the first submissions, on any path, whose limit_was_hit reports the limit
  // hit (render_push::probe_trips 3 instead of 2), to prove the engine redraws what it kept none
  // of.
  std::uint32_t simulated_cuts = 0;
  // Tests only: the entries of the BVH walk's stack in use (RTVK_SPEC_STACK); 0: all of them.
  std::uint32_t stack_entries = 0;
  // Where compiled pipelines are kept between runs (default_cache_folder()); empty: nowhere.
  std::filesystem::path pipeline_cache_folder = {};
};

// Called with the number of samples per pixel finished so far; may be empty.
using sample_progress = std::function<void(int samples_done)>;

// The scene on the GPU, with the same sampling and random numbers as render_cpu: each
// invocation traces a run of its pixel's samples and adds them to exact fixed-point sums that
// stay on the device (sample_sum.h), the BVH (or a linear scan) as options.engine.use_bvh says.
// Throws loop_budget_error, naming the device and the budget, when a single sample needs more
// than the loop budget.
framebuffer render_gpu(gpu_context& ctx, const camera& cam, const scene& s,
                       const render_settings& rs, const sample_progress& progress = {},
                       const gpu_render_options& options = {}, render_stats* stats = nullptr);

// Many views of one scene -- several cameras, the frames of an animation -- drawn together: one
// set-up (scene buffers, BVH, pipeline), and each submission's dispatches cover every view of a
// group (up to RTVK_MAX_VIEWS, or fewer when their sums would not fit one storage buffer), the
// dispatch's z index picking the camera. Each view's framebuffer holds the mean of samples
// [win.sample_begin, win.sample_end) over the window, bit for bit what the view alone gives.
// All views must have the same image size; throws std::invalid_argument otherwise, or for a
// window outside the image.
std::vector<framebuffer> render_gpu_views(gpu_context& ctx, const std::vector<camera>& views,
                                          const scene& s, const render_settings& rs,
                                          const render_window& win,
                                          const sample_progress& progress = {},
                                          const gpu_render_options& options = {},
                                          render_stats* stats = nullptr);

}  // namespace rtvk::gpu
