#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "context.h"
#include "descriptors.h"
#include "vk_handle.h"

namespace rtvk::gpu {

// What a render records of its shader, whichever kind of pipeline runs it: the band renderer
// (host/gpu/render/gpu_engine.cpp) drives a compute_pipeline or a ray_pipeline alike.
class shader_program {
 public:
  virtual ~shader_program() = default;
  // Points the descriptor set at other buffers (same bindings, same types). Only while no
  // submission that uses the set is in flight.
  virtual void rebind(const std::vector<buffer_binding>& bindings) = 0;
  // Binds the pipeline and its descriptor set.
  virtual void bind(VkCommandBuffer cb) const = 0;
  virtual void push(VkCommandBuffer cb, const void* data, std::uint32_t bytes) const = 0;
  // Runs `groups` workgroups in x, y and z (a ray-tracing pipeline: as many launches as their
  // invocations); returns how many commands it recorded.
  virtual std::uint32_t dispatch(VkCommandBuffer cb,
                                 const std::array<std::uint32_t, 3>& groups) const = 0;
  // The pipeline stages its shaders run in, for barriers.
  virtual VkPipelineStageFlags stages() const = 0;
  // Whether bind() has recorded it: lavapipe compiles a pipeline in its first run, which the
  // first bind() tells the context (gpu_context::note_first_run).
  bool bound() const { return bound_; }
  // Whether record_empty_run() is known to make lavapipe compile the pipeline; and, after
  // bind() and push(), a run of no work (no workgroups), for a first run of its own.
  virtual bool has_empty_run() const { return false; }
  virtual void record_empty_run(VkCommandBuffer) const {}

 protected:
  // Marks the pipeline bound, telling the context of its first run.
  void mark_bound(const gpu_context& ctx) const {
    if (!bound_) ctx.note_first_run();
    bound_ = true;
  }

 private:
  mutable bool bound_ = false;
};

// A compute shader with its one descriptor set (set 0), all bindings buffers or acceleration
// structures.
class compute_pipeline : public shader_program {
 public:
  // spec_constants fill specialization constant ids 0, 1, ... in order; `cache`, when given,
  // supplies and keeps the device's compiled code.
  compute_pipeline(const gpu_context& ctx, std::span<const std::uint32_t> spirv,
                   const std::vector<buffer_binding>& bindings, std::uint32_t push_constant_bytes,
                   std::span<const std::uint32_t> spec_constants = {},
                   VkPipelineCache cache = VK_NULL_HANDLE);

  ~compute_pipeline() override;
  compute_pipeline(const compute_pipeline&) = delete;
  compute_pipeline& operator=(const compute_pipeline&) = delete;

  void rebind(const std::vector<buffer_binding>& bindings) override;
  void bind(VkCommandBuffer cb) const override;
  void push(VkCommandBuffer cb, const void* data, std::uint32_t bytes) const override;
  // vkCmdDispatch of `groups` workgroups in x, y and z, split into tiles within the device's
  // maxComputeWorkGroupCount (vkCmdDispatchBase, so gl_GlobalInvocationID is as one dispatch
  // would number it). Returns how many dispatches it recorded.
  std::uint32_t dispatch(VkCommandBuffer cb,
                         const std::array<std::uint32_t, 3>& groups) const override;
  VkPipelineStageFlags stages() const override { return VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT; }
  // lavapipe compiles a compute pipeline's variant before it looks at the workgroup count.
  bool has_empty_run() const override { return true; }
  void record_empty_run(VkCommandBuffer cb) const override { vkCmdDispatch(cb, 0, 0, 0); }

 private:
  const gpu_context& ctx_;  // tells whether the device may still be using the pipeline
  // Destroyed in reverse order: descriptor pool (and its set), pipeline, layouts.
  unique_set_layout set_layout_;
  unique_pipeline_layout layout_;
  unique_pipeline pipeline_;
  unique_descriptor_pool pool_;
  VkDescriptorSet set_ = VK_NULL_HANDLE;  // freed with pool_
};

}  // namespace rtvk::gpu
