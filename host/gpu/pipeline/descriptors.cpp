#include "descriptors.h"

#include "vk_error.h"

namespace rtvk::gpu {

unique_set_layout make_set_layout(VkDevice dev, const std::vector<buffer_binding>& bindings,
                                  VkShaderStageFlags stages) {
  std::vector<VkDescriptorSetLayoutBinding> layout_bindings;
  for (const auto& b : bindings) layout_bindings.push_back({b.binding, b.type, 1, stages, nullptr});
  VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  set_info.bindingCount = std::uint32_t(layout_bindings.size());
  set_info.pBindings = layout_bindings.data();
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  vk_check(vkCreateDescriptorSetLayout(dev, &set_info, nullptr, &set_layout),
           "vkCreateDescriptorSetLayout");
  return unique_set_layout(dev, set_layout);
}

unique_pipeline_layout make_pipeline_layout(VkDevice dev, VkDescriptorSetLayout set_layout,
                                            std::uint32_t push_constant_bytes,
                                            VkShaderStageFlags stages) {
  const VkPushConstantRange push{stages, 0, push_constant_bytes};
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

void write_bindings(VkDevice dev, VkDescriptorSet set,
                    const std::vector<buffer_binding>& bindings) {
  std::vector<VkDescriptorBufferInfo> infos;
  infos.reserve(bindings.size());  // the writes below point into them
  std::vector<VkWriteDescriptorSetAccelerationStructureKHR> structures;
  structures.reserve(bindings.size());
  std::vector<VkWriteDescriptorSet> writes;
  for (const auto& b : bindings) {
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = set;
    w.dstBinding = b.binding;
    w.descriptorCount = 1;
    w.descriptorType = b.type;
    if (b.type == VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR) {
      VkWriteDescriptorSetAccelerationStructureKHR s{
          VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR};
      s.accelerationStructureCount = 1;
      s.pAccelerationStructures = &b.structure;
      structures.push_back(s);
      w.pNext = &structures.back();
    } else {
      infos.push_back({b.buffer, 0, VK_WHOLE_SIZE});
      w.pBufferInfo = &infos.back();
    }
    writes.push_back(w);
  }
  vkUpdateDescriptorSets(dev, std::uint32_t(writes.size()), writes.data(), 0, nullptr);
}

}  // namespace rtvk::gpu
