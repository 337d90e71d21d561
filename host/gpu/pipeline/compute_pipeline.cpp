#include "compute_pipeline.h"

#include <algorithm>

#include "descriptors.h"
#include "vk_error.h"

namespace rtvk::gpu {
namespace {

// spec_constants fill specialization constant ids 0, 1, ... in order.
unique_pipeline make_pipeline(VkDevice dev, VkPipelineLayout layout,
                              std::span<const std::uint32_t> spirv,
                              std::span<const std::uint32_t> spec_constants,
                              VkPipelineCache cache) {
  // Destroyed on return: a pipeline no longer needs its module once it exists.
  const unique_shader_module module = make_shader_module(dev, spirv);
  std::vector<VkSpecializationMapEntry> entries;
  for (std::uint32_t i = 0; i < spec_constants.size(); ++i)
    entries.push_back({i, std::uint32_t(i * sizeof(std::uint32_t)), sizeof(std::uint32_t)});
  const VkSpecializationInfo spec{std::uint32_t(entries.size()), entries.data(),
                                  spec_constants.size_bytes(), spec_constants.data()};
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module.get();
  info.stage.pName = "main";
  info.stage.pSpecializationInfo = entries.empty() ? nullptr : &spec;
  info.layout = layout;
  info.flags = VK_PIPELINE_CREATE_DISPATCH_BASE_BIT;  // dispatch() tiles over the count limits
  VkPipeline pipeline = VK_NULL_HANDLE;
  vk_check(vkCreateComputePipelines(dev, cache, 1, &info, nullptr, &pipeline),
           "vkCreateComputePipelines");
  return unique_pipeline(dev, pipeline);
}

}  // namespace

compute_pipeline::compute_pipeline(const gpu_context& ctx, std::span<const std::uint32_t> spirv,
                                   const std::vector<buffer_binding>& bindings,
                                   std::uint32_t push_constant_bytes,
                                   std::span<const std::uint32_t> spec_constants,
                                   VkPipelineCache cache)
    : ctx_(ctx),
      set_layout_(make_set_layout(ctx.vk(), bindings, VK_SHADER_STAGE_COMPUTE_BIT)),
      layout_(make_pipeline_layout(ctx.vk(), set_layout_.get(), push_constant_bytes,
                                   VK_SHADER_STAGE_COMPUTE_BIT)),
      pipeline_(make_pipeline(ctx.vk(), layout_.get(), spirv, spec_constants, cache)),
      pool_(make_descriptor_pool(ctx.vk(), bindings)),
      set_(allocate_set(ctx.vk(), pool_.get(), set_layout_.get())) {
  write_bindings(ctx.vk(), set_, bindings);
}

compute_pipeline::~compute_pipeline() {
  if (ctx_.lost()) {  // a hung device may still be running it: leak rather than crash
    pool_.release();
    pipeline_.release();
    layout_.release();
    set_layout_.release();
  }
}

void compute_pipeline::rebind(const std::vector<buffer_binding>& bindings) {
  write_bindings(ctx_.vk(), set_, bindings);
}

void compute_pipeline::bind(VkCommandBuffer cb) const {
  mark_bound(ctx_);
  vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.get());
  vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, layout_.get(), 0, 1, &set_, 0,
                          nullptr);
}

void compute_pipeline::push(VkCommandBuffer cb, const void* data, std::uint32_t bytes) const {
  vkCmdPushConstants(cb, layout_.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0, bytes, data);
}

std::uint32_t compute_pipeline::dispatch(VkCommandBuffer cb,
                                         const std::array<std::uint32_t, 3>& groups) const {
  const std::uint32_t* most = ctx_.device().limits.maxComputeWorkGroupCount;
  std::array<std::uint32_t, 3> step{};
  for (int i = 0; i < 3; ++i) step[i] = std::max(1u, std::min(groups[i], most[i]));
  std::uint32_t count = 0;
  for (std::uint32_t z = 0; z < groups[2]; z += step[2])
    for (std::uint32_t y = 0; y < groups[1]; y += step[1])
      for (std::uint32_t x = 0; x < groups[0]; x += step[0]) {
        vkCmdDispatchBase(cb, x, y, z, std::min(step[0], groups[0] - x),
                          std::min(step[1], groups[1] - y), std::min(step[2], groups[2] - z));
        ++count;
      }
  return count;
}

}  // namespace rtvk::gpu
