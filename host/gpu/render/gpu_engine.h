#pragma once
#include <array>
#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "band_commands.h"
#include "band_scheduler.h"
#include "byte_encoding.h"
#include "camera.h"
#include "compute_pipeline.h"
#include "context.h"
#include "device_fit.h"
#include "device_timer.h"
#include "framebuffer.h"
#include "gpu_scene.h"
#include "image_rgb8.h"
#include "pacer.h"
#include "pipeline_cache.h"
#include "readback.h"
#include "render_gpu.h"
#include "render_plan.h"
#include "render_settings.h"
#include "render_targets.h"
#include "sample_sum.h"
#include "scene.h"
#include "scene_accel.h"

namespace rtvk::gpu {

// A scene set up on one device once -- spheres, materials and BVH uploaded, pipelines built on
// first use -- and then drawn as often as a run asks: every view, frame, band, region and
// sample range.
// Each invocation traces a run of its pixel's samples and adds them to exact fixed-point sums,
// so the result does not depend on how samples are batched into dispatches or submissions: on
// one device, the same scene, camera, window and samples give the same bits, however drawn.
// The buffers the dispatches accumulate into grow to the largest request and are kept.
// `ctx` must outlive the engine; the scene is copied to the device and not kept.
class gpu_engine {
 public:
  // Checks the scene's buffers against the device's limits (usage_error naming the buffer),
  // then builds, uploads and waits for them.
  gpu_engine(gpu_context& ctx, const scene& s, const gpu_render_options& options = {});
  // Waits for whatever is still in flight (after an error, a submission may be) before any
  // buffer or pipeline it uses goes.
  ~gpu_engine() { ctx_.wait_all(); }
  gpu_engine(const gpu_engine&) = delete;
  gpu_engine& operator=(const gpu_engine&) = delete;

  // Draws `views` of the scene exactly as render_gpu_views does (same arguments, same result):
  // each pixel's mean, in double.
  std::vector<framebuffer> render_views(const std::vector<camera>& views, const render_settings& rs,
                                        const render_window& win,
                                        const sample_progress& progress = {},
                                        render_stats* stats = nullptr);
  // The same render encoded to 8 bits on the device (tonemap.comp, with rs.encoding()): bit for bit
  // encode_sum of render_sums' sums, and 4 bytes a pixel read back instead of 48.
  std::vector<image_rgb8> render_encoded(const std::vector<camera>& views,
                                         const render_settings& rs, const render_window& win,
                                         const sample_progress& progress = {},
                                         render_stats* stats = nullptr);
  // The same render's sums, as the device holds them.
  std::vector<sum_image> render_sums(const std::vector<camera>& views, const render_settings& rs,
                                     const render_window& win, const sample_progress& progress = {},
                                     render_stats* stats = nullptr);

  // The viewer's accumulation, kept on the device: adds samples [win.sample_begin,
  // win.sample_end) of `cam` to rows [win.y, win.y + win.height) of the image, whose sums stay in
  // the engine between calls (no readback, no clear; a call from sample 0 starts its rows afresh,
  // and every pixel of the rows must hold exactly win.sample_begin samples), then encodes those
  // rows with rs.encoding() into accumulated_bytes(). The window spans the image's width. The bytes
  // are bit for bit render_encoded's for the same samples, however the calls split them.
  // Throws usage_error when the image's sums do not fit one storage buffer (see
  // accumulation_fits).
  void accumulate(const camera& cam, const render_settings& rs, const render_window& win,
                  render_stats* stats = nullptr);
  // Whether a width x height image's sums fit one of the device's storage buffers.
  bool accumulation_fits(int width, int height) const;
  // Makes room for a width x height accumulation and sets its bytes to opaque black (a new
  // size); then accumulated_bytes() holds them. Nothing may be in flight.
  void reset_accumulation(int width, int height);
  // The accumulation's RGBA8 bytes (red in the low byte), row 0 at the top, on the device; the
  // buffer changes with reset_accumulation.
  VkBuffer accumulated_bytes() const { return targets_->bytes.get(); }
  // Those bytes copied back, as RGB (screenshots).
  image_rgb8 read_accumulation(int width, int height);

  // tonemap.comp run on the given sums with this gamma (or encoding): RGBA8 per pixel (red in
  // the low byte). For tests of the encoding at its edges, where a render's sums rarely fall.
  std::vector<std::uint32_t> encode_sums(const std::vector<pixel_sum>& sums, double gamma) {
    return encode_sums(sums, display_encoding{view_transform::gamma, gamma, 0});
  }
  std::vector<std::uint32_t> encode_sums(const std::vector<pixel_sum>& sums,
                                         const display_encoding& e);

  int sum_exponent() const { return exponent_; }           // F of every render of this scene
  double setup_seconds() const { return setup_seconds_; }  // the constructor, wall clock
  // Of which the BVH, and on the hardware paths the acceleration structures.
  double build_seconds() const {
    return scene_->build_seconds() + (accel_ ? accel_->build_seconds() : 0.0);
  }
  // Replaces the scene (the library's edits: a material changed, an object moved): its arrays,
  // BVH and acceleration structures made and uploaded again, the pipelines kept -- bound to the
  // new buffers -- where the scene's switches (gpu_scene::specialize) are the same, which spares
  // their compilation. Waits for what is in flight; passes made over the old device_scene()
  // (aov_pass) must be made again. After a throw the engine must not be used.
  void replace_scene(const scene& s);
  // The scene on the device, uploaded, for other passes over it (aov_pass), and whether it holds
  // the compute BVH (every path but --accel none builds it).
  const gpu_scene& device_scene() const { return *scene_; }
  bool scene_has_bvh() const {
    return options_.engine.use_bvh || options_.engine.traversal != gpu_traversal::compute;
  }
  // What finds the hits: "bvh", "none", "rt-query" or "rt-pipeline" (--accel's words).
  const char* traversal_name() const { return accel_word(options_.engine); }
  const pipeline_cache& cache() const { return cache_; }

 private:
  void draw(const std::vector<camera>& views, const render_settings& rs, const render_window& win,
            readback_kind kind, const sample_progress& progress, render_stats* stats,
            const band_sink& sink);

  // What draw_bands draws with: the render's commands and scheduler, its targets, and whether
  // it counts rays and keeps its sums on the device.
  struct band_tools {
    band_commands& commands;
    band_scheduler& bands;
    render_targets& targets;
    bool count_rays, kept;
  };
  // The render's bands, each as large as the layout and the pacer allow, handed to the sink.
  void draw_bands(const std::vector<camera>& views, const render_window& win,
                  const work_layout& layout, const band_tools& tools,
                  const sample_progress& progress, render_stats* stats, const band_sink& sink);

  void upload();
  // The targets, reallocated (after checking the device's limits) when too small.
  render_targets& targets_for(VkDeviceSize pixels);
  // The pipeline with these switches, built (through the cache) the first time it is asked for.
  const shader_program& pipeline_for(bool jitter, bool lens, bool count_rays, bool lights,
                                     bool calibrated, bool nee);
  const compute_pipeline& tonemap_pipeline();
  void rebind_all();
  // The thresholds of `e` into their buffer (when not there already), and tonemap_style_.
  void write_thresholds(const display_encoding& e);

  std::chrono::steady_clock::time_point start_;  // construction began
  gpu_context& ctx_;
  gpu_render_options options_;  // as given
  std::string scene_name_;      // for messages
  rtvk::sky sky_;               // the scene's, for the push constants
  time_span motion_;            // the scene's: the instants the BVH bounds moving spheres over
  // The scene's arrays as built on the host: kept only while the engine is made.
  std::unique_ptr<gpu_scene::host_arrays> host_arrays_;
  std::vector<buffer_request> scene_buffers_;  // what scene_ holds, for later limit checks
  std::array<std::uint32_t, 2> wg_;            // workgroup size
  std::unique_ptr<gpu_scene> scene_;           // uploaded once, or again by replace_scene
  std::unique_ptr<render_targets> targets_;    // grown on demand
  pipeline_cache cache_;                       // compiled code, kept between runs
  // One per combination of the render's switches (specialization constants), made on first use.
  std::map<std::uint32_t, std::unique_ptr<shader_program>> pipelines_;
  // The hardware paths' acceleration structures (none on the compute path), and rt-pipeline's
  // rays' times (one float per pixel of the targets).
  std::unique_ptr<scene_accel> accel_;
  std::unique_ptr<gpu_buffer> ray_times_;
  // The stages the render's shaders run in: compute, and a ray-tracing pipeline's.
  VkPipelineStageFlags render_stages_ = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
  std::uint32_t trace_cost_ = 1;               // render_push::trace_cost (gpu_engine.cpp)
  std::uint32_t simulated_cuts_ = 0;           // gpu_render_options::simulated_cuts still to make
  std::unique_ptr<compute_pipeline> tonemap_;  // made on first use
  device_timer timer_;                         // device time of each submission
  int exponent_;                               // F of the sums (sample_sum.h)
  std::optional<display_encoding> thresholds_for_;  // what the thresholds buffer holds, if any
  tonemap_push tonemap_style_ = {};                 // tonemap.comp's transform and mean scale
  bool drawn_ = false;                              // some band was drawn before
  bool built_drawn_ = false;  // a render was drawn since the scene's BVH was built (stats)
  pacer pacer_;               // samples per dispatch and per submission, from measured times
  double setup_seconds_ = 0;  // the constructor took
};

}  // namespace rtvk::gpu
