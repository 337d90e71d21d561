// An engine's scene replaced in place (gpu_engine::replace_scene): what the library's edits cost
// on the GPU is then the scene's upload and trees, not the pipelines' compilation (on lavapipe
// about a second each; scripts/bench-python-edits.py).
#include <array>

#include "errors.h"
#include "gpu_engine.h"
#include "gpu_scene.h"
#include "render_plan.h"
#include "render_targets.h"
#include "sample_sum.h"
#include "scene_accel.h"

namespace rtvk::gpu {

void gpu_engine::replace_scene(const scene& s) {
  ctx_.wait_all();
  std::array<std::uint32_t, RTVK_SPEC_COUNT> before{}, after{};
  scene_->specialize(before);
  const gpu_scene::host_arrays arrays = gpu_scene::build(s, scene_has_bvh());
  std::vector<buffer_request> buffers = gpu_scene::buffers(ctx_, arrays);
  std::vector<buffer_request> wanted = render_targets::buffers(buffers, targets_->pixels);
  if (ray_times_)  // as targets_for asks for it
    wanted.push_back(
        {"the rays' times", targets_->pixels * sizeof(float), true, memory_use::device_local});
  check_device_fits(ctx_, wanted, "--scene " + s.name);
  accel_.reset();  // the old scene's structures and buffers go first, to make room
  scene_.reset();
  scene_ = std::make_unique<gpu_scene>(ctx_, arrays);
  scene_buffers_ = std::move(buffers);
  upload();
  if (options_.engine.traversal != gpu_traversal::compute)
    accel_ = std::make_unique<scene_accel>(
        ctx_, arrays, s.motion, std::string("--accel ") + traversal_name() + " --scene " + s.name);
  built_drawn_ = false;  // the next render's stats carry the new BVH's build
  scene_name_ = s.name;
  sky_ = s.sky;
  motion_ = s.motion;
  const int exponent = rtvk::sum_exponent(brightest(s.sky));
  if (exponent != exponent_) thresholds_for_.reset();  // the byte thresholds scale with it
  exponent_ = exponent;
  scene_->specialize(after);
  if (before != after)
    pipelines_.clear();  // made again, with the new switches, when first asked for
  else
    rebind_all();
}

}  // namespace rtvk::gpu
