#include "compute_pipeline.h"

#include <algorithm>

#include "vk_error.h"

namespace rtvk::gpu {
namespace {

unique_set_layout make_set_layout(VkDevice dev, const std::vector<buffer_binding>& bindings) {
  std::vector<VkDescriptorSetLayoutBinding> layout_bindings;
  for (const auto& b : bindings)
    layout_bindings.push_back({b.binding, b.type, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
  VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  set_info.bindingCount = std::uint32_t(layout_bindings.size());
  set_info.pBindings = layout_bindings.data();
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  vk_check(vkCreateDescriptorSetLayout(dev, &set_info, nullptr, &set_layout),
           "vkCreateDescriptorSetLayout");
  return unique_set_layout(dev, set_layout);
}

unique_pipeline_layout make_pipeline_layout(VkDevice dev, VkDescriptorSetLayout set_layout,
                                            std::uint32_t push_constant_bytes) {
  const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, push_constant_bytes};
  VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layout_info.setLayoutCount = 1;
  layout_info.pSetLayouts = &set_layout;
  layout_info.pushConstantRangeCount = push_constant_bytes ? 1 : 0;
  layout_info.pPushConstantRanges = &push;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  vk_check(vkCreatePipelineLayout(dev, &layout_info, nullptr, &layout), "vkCreatePipelineLayout");
  return unique_pipeline_layout(dev, layout);
}

unique_shader_module make_shader_module(VkDevice dev, std::span<const std::uint32_t> spirv) {
  VkShaderModuleCreateInfo module_info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  module_info.codeSize = spirv.size_bytes();
  module_info.pCode = spirv.data();
  VkShaderModule raw_module = VK_NULL_HANDLE;
  vk_check(vkCreateShaderModule(dev, &module_info, nullptr, &raw_module), "vkCreateShaderModule");
  return unique_shader_module(dev, raw_module);
}

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

// Room for exactly one set holding every binding.
unique_descriptor_pool make_descriptor_pool(VkDevice dev,
                                            const std::vector<buffer_binding>& bindings) {
  std::vector<VkDescriptorPoolSize> sizes;
  for (const auto& b : bindings) sizes.push_back({b.type, 1});
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.maxSets = 1;
  pool_info.poolSizeCount = std::uint32_t(sizes.size());
  pool_info.pPoolSizes = sizes.data();
  VkDescriptorPool pool = VK_NULL_HANDLE;
  vk_check(vkCreateDescriptorPool(dev, &pool_info, nullptr, &pool), "vkCreateDescriptorPool");
  return unique_descriptor_pool(dev, pool);
}

VkDescriptorSet allocate_set(VkDevice dev, VkDescriptorPool pool,
                             VkDescriptorSetLayout set_layout) {
  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = pool;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = &set_layout;
  VkDescriptorSet set = VK_NULL_HANDLE;
  vk_check(vkAllocateDescriptorSets(dev, &alloc, &set), "vkAllocateDescriptorSets");
  return set;
}

// Points each binding of `set` at its buffer, whole.
void write_bindings(VkDevice dev, VkDescriptorSet set,
                    const std::vector<buffer_binding>& bindings) {
  std::vector<VkDescriptorBufferInfo> infos;
  infos.reserve(bindings.size());  // the writes below point into it
  std::vector<VkWriteDescriptorSet> writes;
  for (const auto& b : bindings) {
    infos.push_back({b.buffer, 0, VK_WHOLE_SIZE});
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = set;
    w.dstBinding = b.binding;
    w.descriptorCount = 1;
    w.descriptorType = b.type;
    w.pBufferInfo = &infos.back();
    writes.push_back(w);
  }
  vkUpdateDescriptorSets(dev, std::uint32_t(writes.size()), writes.data(), 0, nullptr);
}

}  // namespace

compute_pipeline::compute_pipeline(const gpu_context& ctx, std::span<const std::uint32_t> spirv,
                                   const std::vector<buffer_binding>& bindings,
                                   std::uint32_t push_constant_bytes,
                                   std::span<const std::uint32_t> spec_constants,
                                   VkPipelineCache cache)
    : ctx_(ctx),
      set_layout_(make_set_layout(ctx.vk(), bindings)),
      layout_(make_pipeline_layout(ctx.vk(), set_layout_.get(), push_constant_bytes)),
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
