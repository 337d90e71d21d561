#pragma once
#include <memory>
#include <vector>

#include "buffer.h"
#include "camera.h"
#include "compute_pipeline.h"
#include "context.h"
#include "gpu_scene.h"
#include "render_settings.h"
#include "scene.h"
#include "shared_types.h"

namespace rtvk::gpu {

// aov.comp: the first hit of the ray through each pixel center of a window (row-major from its
// top row), on the device, through a scene already there -- the render's own (gpu_engine::
// device_scene), so a run's AOVs build no tree and upload nothing of their own -- through its
// BVH, or every object in turn where it has none. The pipeline is made once; each image only
// writes its camera and reads its rows back.
class aov_pass {
 public:
  // `g` uploaded (gpu_engine's is), and kept alive while the pass is used.
  aov_pass(gpu_context& ctx, const gpu_scene& g, bool use_bvh);
  std::vector<gpu_aov> run(const camera& cam, const render_window& win);

 private:
  std::vector<buffer_binding> bindings() const;

  gpu_context& ctx_;
  const gpu_scene& scene_;
  bool use_bvh_;
  gpu_buffer camera_;                           // one camera_ubo
  std::unique_ptr<gpu_buffer> out_;             // a band of rows' gpu_aov, grown on demand
  std::unique_ptr<compute_pipeline> pipeline_;  // made with the first band's buffer
};

// The pass over a scene put on the device for it alone (tests; rtvk render uses the render's).
std::vector<gpu_aov> run_aov_pass(gpu_context& ctx, const scene& s, bool use_bvh, const camera& cam,
                                  const render_window& win);

}  // namespace rtvk::gpu
