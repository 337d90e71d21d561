#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "buffer.h"
#include "compute_pipeline.h"
#include "context.h"
#include "descriptors.h"
#include "vk_handle.h"

namespace rtvk::gpu {

// The shaders of a ray-tracing pipeline (SPIR-V): one ray generation, one miss, and the hit
// groups -- boxes (an intersection and an any-hit shader) and triangles (the same any-hit).
struct ray_shaders {
  std::span<const std::uint32_t> raygen;
  std::span<const std::uint32_t> miss;
  std::span<const std::uint32_t> intersection;
  std::span<const std::uint32_t> any_hit;
};

// A ray-tracing pipeline (VK_KHR_ray_tracing_pipeline) with its one descriptor set and its
// shader binding table: hit group 0 for box geometries, 1 for triangles (an instance's
// instanceShaderBindingTableRecordOffset picks where its geometries start). One ray, no
// recursion. Driven like a compute_pipeline: dispatch() launches workgroup-sized blocks.
class ray_pipeline : public shader_program {
 public:
  // `workgroup`: the block of launches one "workgroup" of dispatch() stands for.
  ray_pipeline(const gpu_context& ctx, const ray_shaders& shaders,
               const std::vector<buffer_binding>& bindings, std::uint32_t push_constant_bytes,
               std::span<const std::uint32_t> spec_constants, VkPipelineCache cache,
               std::array<std::uint32_t, 2> workgroup);
  ~ray_pipeline() override;
  ray_pipeline(const ray_pipeline&) = delete;
  ray_pipeline& operator=(const ray_pipeline&) = delete;

  void rebind(const std::vector<buffer_binding>& bindings) override;
  void bind(VkCommandBuffer cb) const override;
  void push(VkCommandBuffer cb, const void* data, std::uint32_t bytes) const override;
  // One vkCmdTraceRaysKHR of groups x workgroup launches (throws when past the device's
  // maxRayDispatchInvocationCount, which rtvk's bands stay far inside).
  std::uint32_t dispatch(VkCommandBuffer cb,
                         const std::array<std::uint32_t, 3>& groups) const override;
  VkPipelineStageFlags stages() const override {
    return VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR;
  }

 private:
  const gpu_context& ctx_;
  std::array<std::uint32_t, 2> workgroup_;
  std::uint32_t max_invocations_ = 0;  // maxRayDispatchInvocationCount
  unique_set_layout set_layout_;
  unique_pipeline_layout layout_;
  unique_pipeline pipeline_;
  std::unique_ptr<gpu_buffer> table_;  // the shader binding table
  VkStridedDeviceAddressRegionKHR raygen_{}, miss_{}, hit_{}, callable_{};
  unique_descriptor_pool pool_;
  VkDescriptorSet set_ = VK_NULL_HANDLE;  // freed with pool_
};

}  // namespace rtvk::gpu
