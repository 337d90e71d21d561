#include "ray_pipeline.h"

#include <cstring>
#include <stdexcept>
#include <string>

#include "acceleration_structure.h"
#include "vk_error.h"

namespace rtvk::gpu {
namespace {

constexpr VkShaderStageFlags ray_stages =
    VK_SHADER_STAGE_RAYGEN_BIT_KHR | VK_SHADER_STAGE_MISS_BIT_KHR |
    VK_SHADER_STAGE_INTERSECTION_BIT_KHR | VK_SHADER_STAGE_ANY_HIT_BIT_KHR;

VkDeviceSize align_up(VkDeviceSize v, VkDeviceSize a) {
  return (v + a - 1) / a * a;
}

VkPhysicalDeviceRayTracingPipelinePropertiesKHR pipeline_limits(const gpu_context& ctx) {
  VkPhysicalDeviceRayTracingPipelinePropertiesKHR rt{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_PROPERTIES_KHR};
  VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  props.pNext = &rt;
  vkGetPhysicalDeviceProperties2(ctx.device().handle, &props);
  return rt;
}

VkRayTracingShaderGroupCreateInfoKHR group(VkRayTracingShaderGroupTypeKHR type,
                                           std::uint32_t general, std::uint32_t intersection,
                                           std::uint32_t any_hit) {
  VkRayTracingShaderGroupCreateInfoKHR g{
      VK_STRUCTURE_TYPE_RAY_TRACING_SHADER_GROUP_CREATE_INFO_KHR};
  g.type = type;
  g.generalShader = general;
  g.closestHitShader = VK_SHADER_UNUSED_KHR;
  g.anyHitShader = any_hit;
  g.intersectionShader = intersection;
  return g;
}

}  // namespace

ray_pipeline::ray_pipeline(const gpu_context& ctx, const ray_shaders& shaders,
                           const std::vector<buffer_binding>& bindings,
                           std::uint32_t push_constant_bytes,
                           std::span<const std::uint32_t> spec_constants, VkPipelineCache cache,
                           std::array<std::uint32_t, 2> workgroup)
    : ctx_(ctx),
      workgroup_(workgroup),
      set_layout_(make_set_layout(ctx.vk(), bindings, ray_stages)),
      layout_(make_pipeline_layout(ctx.vk(), set_layout_.get(), push_constant_bytes, ray_stages)),
      pool_(make_descriptor_pool(ctx.vk(), bindings)),
      set_(allocate_set(ctx.vk(), pool_.get(), set_layout_.get())) {
  const VkDevice dev = ctx.vk();
  const unique_shader_module modules[] = {
      make_shader_module(dev, shaders.raygen), make_shader_module(dev, shaders.miss),
      make_shader_module(dev, shaders.intersection), make_shader_module(dev, shaders.any_hit)};
  const VkShaderStageFlagBits kinds[] = {
      VK_SHADER_STAGE_RAYGEN_BIT_KHR, VK_SHADER_STAGE_MISS_BIT_KHR,
      VK_SHADER_STAGE_INTERSECTION_BIT_KHR, VK_SHADER_STAGE_ANY_HIT_BIT_KHR};
  std::vector<VkSpecializationMapEntry> entries;
  for (std::uint32_t i = 0; i < spec_constants.size(); ++i)
    entries.push_back({i, std::uint32_t(i * sizeof(std::uint32_t)), sizeof(std::uint32_t)});
  const VkSpecializationInfo spec{std::uint32_t(entries.size()), entries.data(),
                                  spec_constants.size_bytes(), spec_constants.data()};
  VkPipelineShaderStageCreateInfo stages[4];
  for (int k = 0; k < 4; ++k) {
    stages[k] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    stages[k].stage = kinds[k];
    stages[k].module = modules[k].get();
    stages[k].pName = "main";
    stages[k].pSpecializationInfo = entries.empty() ? nullptr : &spec;
  }
  const VkRayTracingShaderGroupCreateInfoKHR groups[] = {
      group(VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR, 0, VK_SHADER_UNUSED_KHR,
            VK_SHADER_UNUSED_KHR),
      group(VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR, 1, VK_SHADER_UNUSED_KHR,
            VK_SHADER_UNUSED_KHR),
      group(VK_RAY_TRACING_SHADER_GROUP_TYPE_PROCEDURAL_HIT_GROUP_KHR, VK_SHADER_UNUSED_KHR, 2, 3),
      group(VK_RAY_TRACING_SHADER_GROUP_TYPE_TRIANGLES_HIT_GROUP_KHR, VK_SHADER_UNUSED_KHR,
            VK_SHADER_UNUSED_KHR, 3)};
  VkRayTracingPipelineCreateInfoKHR info{VK_STRUCTURE_TYPE_RAY_TRACING_PIPELINE_CREATE_INFO_KHR};
  info.stageCount = 4;
  info.pStages = stages;
  info.groupCount = 4;
  info.pGroups = groups;
  info.maxPipelineRayRecursionDepth = 1;
  info.layout = layout_.get();
  VkPipeline pipeline = VK_NULL_HANDLE;
  vk_check(vkCreateRayTracingPipelinesKHR(dev, VK_NULL_HANDLE, cache, 1, &info, nullptr, &pipeline),
           "vkCreateRayTracingPipelinesKHR");
  pipeline_ = unique_pipeline(dev, pipeline);

  // The table: ray generation, miss, then the two hit groups, each region on the base alignment.
  const auto limits = pipeline_limits(ctx);
  max_invocations_ = limits.maxRayDispatchInvocationCount;
  const std::uint32_t handle = limits.shaderGroupHandleSize;
  const VkDeviceSize stride = align_up(handle, limits.shaderGroupHandleAlignment);
  const VkDeviceSize region = align_up(2 * stride, limits.shaderGroupBaseAlignment);
  std::vector<std::uint8_t> handles(4 * handle);
  vk_check(
      vkGetRayTracingShaderGroupHandlesKHR(dev, pipeline, 0, 4, handles.size(), handles.data()),
      "vkGetRayTracingShaderGroupHandlesKHR");
  const VkDeviceSize offsets[] = {0, region, 2 * region, 2 * region + stride};
  std::vector<std::uint8_t> table(3 * region, 0);
  for (int k = 0; k < 4; ++k)
    std::memcpy(table.data() + offsets[k], handles.data() + std::size_t(k) * handle, handle);
  table_ = std::make_unique<gpu_buffer>(
      ctx, table.size() + limits.shaderGroupBaseAlignment,
      VK_BUFFER_USAGE_SHADER_BINDING_TABLE_BIT_KHR | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
      memory_use::upload);
  // The regions start on the base alignment, wherever the buffer's address falls.
  const VkDeviceAddress address = device_address(ctx, table_->get());
  const VkDeviceAddress base = align_up(address, limits.shaderGroupBaseAlignment);
  std::vector<std::uint8_t> placed(table_->size(), 0);
  std::memcpy(placed.data() + (base - address), table.data(), table.size());
  table_->write(placed.data(), placed.size());
  raygen_ = {base, stride, stride};
  miss_ = {base + region, stride, stride};
  hit_ = {base + 2 * region, stride, 2 * stride};
  write_bindings(dev, set_, bindings);
}

ray_pipeline::~ray_pipeline() {
  if (ctx_.lost()) {  // a hung device may still be running it: leak rather than crash
    pool_.release();
    pipeline_.release();
    layout_.release();
    set_layout_.release();
  }
}

void ray_pipeline::rebind(const std::vector<buffer_binding>& bindings) {
  write_bindings(ctx_.vk(), set_, bindings);
}

void ray_pipeline::bind(VkCommandBuffer cb) const {
  mark_bound(ctx_);
  vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, pipeline_.get());
  vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, layout_.get(), 0, 1, &set_, 0,
                          nullptr);
}

void ray_pipeline::push(VkCommandBuffer cb, const void* data, std::uint32_t bytes) const {
  vkCmdPushConstants(cb, layout_.get(), ray_stages, 0, bytes, data);
}

std::uint32_t ray_pipeline::dispatch(VkCommandBuffer cb,
                                     const std::array<std::uint32_t, 3>& groups) const {
  const std::uint64_t w = std::uint64_t(groups[0]) * workgroup_[0];
  const std::uint64_t h = std::uint64_t(groups[1]) * workgroup_[1];
  if (w * h * groups[2] > max_invocations_)
    throw std::runtime_error("vkCmdTraceRaysKHR: " + std::to_string(w * h * groups[2]) +
                             " launches, past the device's maxRayDispatchInvocationCount " +
                             std::to_string(max_invocations_));
  vkCmdTraceRaysKHR(cb, &raygen_, &miss_, &hit_, &callable_, std::uint32_t(w), std::uint32_t(h),
                    groups[2]);
  return 1;
}

}  // namespace rtvk::gpu
