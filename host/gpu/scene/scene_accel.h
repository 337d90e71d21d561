#pragma once
#include <memory>
#include <string>
#include <vector>

#include "acceleration_structure.h"
#include "context.h"
#include "gpu_scene.h"
#include "sphere.h"

namespace rtvk::gpu {

// The scene as the driver's acceleration structures (--accel rt-query, rt-pipeline), built on the
// device from the same arrays gpu_scene uploads: one bottom level per group of objects -- the
// scene's own, and each distinct group its instances place -- with one geometry of boxes (the
// group's spheres, each box covering it over the scene's motion span, then its quads) and one of
// triangles, which the driver intersects itself; and a top level with the scene's own objects
// (custom index 0) and every instance (custom index k + 1, its placement as the transform). What
// world_rt.glsl reads. Bottom levels are compacted. Nothing is opaque: the shaders test every
// candidate themselves, so the hits are the compute path's.
class scene_accel {
 public:
  // Checks the device's limits first (usage_error beginning with `subject`, naming the limit:
  // maxPrimitiveCount, maxInstanceCount and the custom index's 24 bits, the structures', the
  // scratch's and the inputs' sizes against the allocation and heap limits; each bottom level
  // has one geometry), then builds and waits.
  scene_accel(gpu_context& ctx, const gpu_scene::host_arrays& a, time_span motion,
              const std::string& subject);

  VkAccelerationStructureKHR top() const { return top_ ? top_->get() : VK_NULL_HANDLE; }
  double build_seconds() const { return build_seconds_; }
  VkDeviceSize bytes() const;  // the structures' device memory, compacted

 private:
  std::vector<std::unique_ptr<acceleration_structure>> bottoms_;
  std::unique_ptr<acceleration_structure> top_;
  double build_seconds_ = 0;
};

}  // namespace rtvk::gpu
