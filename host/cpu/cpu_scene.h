#pragma once
// A scene set up for the CPU once and drawn any number of times, as the GPU engine keeps its
// device scene: its world (rtvk's BVH or the lesson's list for the reference, Embree's trees over
// the GPU's arrays for the fast mode) built when it is made, and the shading tables of each
// sampling kept after their first render. render_cpu makes one for a single render; `rtvk render`
// keeps one for every view and frame of a run, the library's Renderer across its renders.
#include <array>
#include <memory>
#include <mutex>
#include <vector>

#include "camera.h"
#include "engine_options.h"
#include "framebuffer.h"
#include "render_settings.h"
#include "scene.h"
#include "shared_types.h"

namespace rtvk {

class hittable;
class bvh_world;
class fast_scene;
struct scene_shading;

// Called with the number of rows finished so far; may be empty.
using progress_callback = std::function<void(int rows_done)>;

class cpu_scene {
 public:
  // Over `s`, which must outlive this and not change. engine.precision, use_bvh and threads
  // decide what is built (runs_fast: the fast mode's).
  cpu_scene(const scene& s, const engine_options& engine);
  ~cpu_scene();
  cpu_scene(const cpu_scene&) = delete;
  cpu_scene& operator=(const cpu_scene&) = delete;

  // render_cpu_window's image of the window. Of `engine` only threads, cancelled and count_rays
  // are read; stats->build_seconds is 0 (build_seconds() has the set-up's).
  framebuffer render(const camera& cam, const render_settings& rs, const render_window& win,
                     const progress_callback& progress, const engine_options& engine,
                     render_stats* stats) const;
  // render_aov_cpu's ground truth of the window, from a BVH over the scene kept after its first
  // use (the reference's own where it is one).
  std::vector<gpu::gpu_aov> aovs(const camera& cam, const render_window& win, int threads) const;

  bool fast() const { return fast_ != nullptr; }
  double build_seconds() const { return build_seconds_; }  // making the world, seconds
  const scene& source() const { return s_; }

 private:
  const scene_shading& shading(bool sample_lights, bool nee) const;
  framebuffer render_reference(const camera& cam, const render_settings& rs,
                               const render_window& win, const progress_callback& progress,
                               const engine_options& engine, render_stats* stats) const;

  const scene& s_;
  std::unique_ptr<hittable> world_;   // the reference's
  std::unique_ptr<fast_scene> fast_;  // the fast mode's
  double build_seconds_ = 0;
  mutable std::mutex mutex_;  // guards what is made on first use below
  mutable std::array<std::unique_ptr<scene_shading>, 4> shading_;  // by sample_lights + 2 nee
  mutable std::unique_ptr<bvh_world> aov_world_;  // where world_ is not a bvh_world
};

}  // namespace rtvk
