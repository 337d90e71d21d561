#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "context.h"
#include "vk_handle.h"

namespace rtvk::gpu {

struct buffer_binding {
  std::uint32_t binding;  // layout(binding = N) in the shader
  VkDescriptorType type;  // uniform or storage buffer
  VkBuffer buffer;        // bound over its whole range
};

// A compute shader with its one descriptor set (set 0), all bindings buffers.
class compute_pipeline {
 public:
  // spec_constants fill specialization constant ids 0, 1, ... in order; `cache`, when given,
  // supplies and keeps the device's compiled code.
  compute_pipeline(const gpu_context& ctx, std::span<const std::uint32_t> spirv,
                   const std::vector<buffer_binding>& bindings, std::uint32_t push_constant_bytes,
                   std::span<const std::uint32_t> spec_constants = {},
                   VkPipelineCache cache = VK_NULL_HANDLE);

  ~compute_pipeline();
  compute_pipeline(const compute_pipeline&) = delete;
  compute_pipeline& operator=(const compute_pipeline&) = delete;

  // Points the descriptor set at other buffers (same bindings, same types). Only while no
  // submission that uses the set is in flight.
  void rebind(const std::vector<buffer_binding>& bindings);

  // Binds the pipeline and its descriptor set.
  void bind(VkCommandBuffer cb) const;
  void push(VkCommandBuffer cb, const void* data, std::uint32_t bytes) const;
  // vkCmdDispatch of `groups` workgroups in x, y and z, split into tiles within the device's
  // maxComputeWorkGroupCount (vkCmdDispatchBase, so gl_GlobalInvocationID is as one dispatch
  // would number it). Returns how many dispatches it recorded.
  std::uint32_t dispatch(VkCommandBuffer cb, const std::array<std::uint32_t, 3>& groups) const;

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
