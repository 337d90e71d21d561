#include "render_gpu.h"

#include <algorithm>
#include <array>

#include "buffer.h"
#include "compute_pipeline.h"
#include "format.h"
#include "packing.h"
#include "shaders.h"

namespace rtvk::gpu {
namespace {

// 8x8 unless the device's limits are smaller (the Vulkan minimum is 128 invocations).
std::array<std::uint32_t, 2> workgroup_size(const VkPhysicalDeviceLimits& l) {
  std::uint32_t x = std::min(8u, l.maxComputeWorkGroupSize[0]);
  std::uint32_t y = std::min(8u, l.maxComputeWorkGroupSize[1]);
  while (x * y > l.maxComputeWorkGroupInvocations) y > 1 ? y /= 2 : x /= 2;
  return {x, y};
}

void barrier(VkCommandBuffer cb, VkPipelineStageFlags src_stage, VkAccessFlags src,
             VkPipelineStageFlags dst_stage, VkAccessFlags dst) {
  VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  b.srcAccessMask = src;
  b.dstAccessMask = dst;
  vkCmdPipelineBarrier(cb, src_stage, dst_stage, 0, 1, &b, 0, nullptr, 0, nullptr);
}

}  // namespace

framebuffer render_gpu(gpu_context& ctx, const camera& cam, const scene& s) {
  const std::uint32_t width = std::uint32_t(cam.image_width());
  const std::uint32_t height = std::uint32_t(cam.image_height());
  const VkDeviceSize image_bytes = VkDeviceSize(width) * height * 3 * sizeof(float);
  const auto& limits = ctx.device().limits;
  if (image_bytes > limits.maxStorageBufferRange)
    throw std::runtime_error(std::to_string(width) + "x" + std::to_string(height) + " needs a " +
                             format_number(double(image_bytes) / (1 << 20)) +
                             " MiB storage buffer; " + ctx.device().name + " allows " +
                             format_number(double(limits.maxStorageBufferRange) / (1 << 20)) +
                             " MiB");

  const camera_ubo ubo = to_ubo(cam);
  std::vector<gpu_sphere> spheres = to_gpu_spheres(s);
  const render_push push{std::uint32_t(spheres.size()), 0, 0, 0};
  if (spheres.empty()) spheres.push_back({});  // a buffer cannot be empty; sphere_count says 0
  const VkDeviceSize sphere_bytes = spheres.size() * sizeof(gpu_sphere);

  gpu_buffer ubo_buf(ctx, sizeof ubo, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, memory_use::upload);
  ubo_buf.write(&ubo, sizeof ubo);
  gpu_buffer staging(ctx, sphere_bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, memory_use::upload);
  staging.write(spheres.data(), sphere_bytes);
  gpu_buffer sphere_buf(ctx, sphere_bytes,
                        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                        memory_use::device_local);
  gpu_buffer image_buf(ctx, image_bytes,
                       VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                       memory_use::device_local);
  gpu_buffer readback(ctx, image_bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, memory_use::readback);

  const auto wg = workgroup_size(limits);
  const compute_pipeline pipeline(
      ctx, render_shader(),
      {{RTVK_BINDING_CAMERA, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, ubo_buf.get()},
       {RTVK_BINDING_SPHERES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, sphere_buf.get()},
       {RTVK_BINDING_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, image_buf.get()}},
      sizeof(render_push), wg);

  ctx.submit_and_wait([&](VkCommandBuffer cb) {
    const VkBufferCopy spheres_copy{0, 0, sphere_bytes};
    vkCmdCopyBuffer(cb, staging.get(), sphere_buf.get(), 1, &spheres_copy);
    barrier(cb, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
            VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
    pipeline.bind(cb);
    pipeline.push(cb, &push, sizeof push);
    vkCmdDispatch(cb, (width + wg[0] - 1) / wg[0], (height + wg[1] - 1) / wg[1], 1);
    barrier(cb, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
            VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
    const VkBufferCopy image_copy{0, 0, image_bytes};
    vkCmdCopyBuffer(cb, image_buf.get(), readback.get(), 1, &image_copy);
    barrier(cb, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
            VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
  });

  const float* rgb = static_cast<const float*>(readback.read());
  framebuffer fb{int(width), int(height)};
  for (std::uint32_t y = 0; y < height; ++y)
    for (std::uint32_t x = 0; x < width; ++x, rgb += 3)
      fb.at(int(x), int(y)) = color(rgb[0], rgb[1], rgb[2]);
  return fb;
}

}  // namespace rtvk::gpu
