#pragma once
// The one descriptor set of rtvk's pipelines (set 0) and their layouts, for compute_pipeline and
// ray_pipeline alike.
#include <cstdint>
#include <span>
#include <vector>

#include "vk_handle.h"

namespace rtvk::gpu {

struct buffer_binding {
  std::uint32_t binding;  // layout(binding = N) in the shader
  VkDescriptorType type;  // uniform or storage buffer, or acceleration structure
  VkBuffer buffer;        // bound over its whole range (buffers)
  VkAccelerationStructureKHR structure = VK_NULL_HANDLE;  // the acceleration structure bound
};

// A set layout with every binding, visible to `stages`.
unique_set_layout make_set_layout(VkDevice dev, const std::vector<buffer_binding>& bindings,
                                  VkShaderStageFlags stages);
// A pipeline layout of that one set and `push_constant_bytes` of push constants for `stages`.
unique_pipeline_layout make_pipeline_layout(VkDevice dev, VkDescriptorSetLayout set_layout,
                                            std::uint32_t push_constant_bytes,
                                            VkShaderStageFlags stages);
unique_shader_module make_shader_module(VkDevice dev, std::span<const std::uint32_t> spirv);
// Room for exactly one set holding every binding.
unique_descriptor_pool make_descriptor_pool(VkDevice dev,
                                            const std::vector<buffer_binding>& bindings);
VkDescriptorSet allocate_set(VkDevice dev, VkDescriptorPool pool, VkDescriptorSetLayout set_layout);
// Points each binding of `set` at its buffer (whole) or acceleration structure.
void write_bindings(VkDevice dev, VkDescriptorSet set, const std::vector<buffer_binding>& bindings);

}  // namespace rtvk::gpu
