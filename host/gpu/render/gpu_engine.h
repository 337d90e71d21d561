#pragma once
#include <array>
#include <chrono>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "camera.h"
#include "compute_pipeline.h"
#include "context.h"
#include "device_fit.h"
#include "device_timer.h"
#include "framebuffer.h"
#include "gpu_scene.h"
#include "pipeline_cache.h"
#include "render_gpu.h"
#include "render_settings.h"
#include "render_targets.h"
#include "scene.h"

namespace rtvk::gpu {

// A scene set up on one device once -- spheres, materials and BVH uploaded, pipelines built on
// first use -- and then drawn as often as a run asks: every view, frame, band, region and
// sample range.
// The buffers the dispatches accumulate into grow to the largest request and are kept.
// `ctx` must outlive the engine; the scene is copied to the device and not kept.
class gpu_engine {
 public:
  // Checks the scene's buffers against the device's limits (usage_error naming the buffer),
  // then builds, uploads and waits for them.
  gpu_engine(gpu_context& ctx, const scene& s, const gpu_render_options& options = {});

  // Draws `views` of the scene exactly as render_gpu_views does (same arguments, same result).
  std::vector<framebuffer> render_views(const std::vector<camera>& views, const render_settings& rs,
                                        const render_window& win,
                                        const sample_progress& progress = {},
                                        render_stats* stats = nullptr);

  double setup_seconds() const { return setup_seconds_; }          // the constructor, wall clock
  double build_seconds() const { return scene_.build_seconds(); }  // of which the BVH
  const pipeline_cache& cache() const { return cache_; }

 private:
  void upload();
  // The targets, reallocated (after checking the device's limits) when too small.
  render_targets& targets_for(VkDeviceSize image_bytes, VkDeviceSize count_bytes);
  // The pipeline with these switches, built (through the cache) the first time it is asked for.
  const compute_pipeline& pipeline_for(bool jitter, bool lens, bool count_rays);

  std::chrono::steady_clock::time_point start_;  // construction began
  gpu_context& ctx_;
  gpu_render_options options_;                 // as given
  std::string scene_name_;                     // for messages
  rtvk::sky sky_;                              // the scene's, for the push constants
  std::vector<buffer_request> scene_buffers_;  // what scene_ holds, for later limit checks
  std::array<std::uint32_t, 2> wg_;            // workgroup size
  gpu_scene scene_;                            // uploaded once
  std::unique_ptr<render_targets> targets_;    // grown on demand
  pipeline_cache cache_;                       // compiled code, kept between runs
  // One per combination of the render's switches (specialization constants), made on first use.
  std::map<std::uint32_t, std::unique_ptr<compute_pipeline>> pipelines_;
  device_timer timer_;        // device time of each submission
  bool drawn_ = false;        // some band was drawn before
  int batch_ = 1;             // samples per submission, grows to 256
  double setup_seconds_ = 0;  // the constructor took
};

}  // namespace rtvk::gpu
