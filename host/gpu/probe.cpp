#include "probe.h"

#include <cstring>

#include "buffer.h"
#include "compute_pipeline.h"
#include "packing.h"
#include "shaders.h"

namespace rtvk::gpu {

probe_io run_probe(gpu_context& ctx, const camera& cam,
                   const std::array<glm::vec2, RTVK_PROBE_POINTS>& uv) {
  const camera_ubo ubo = to_ubo(cam);
  probe_io io{};
  for (int k = 0; k < RTVK_PROBE_POINTS; ++k) io.uv[k] = vec4(uv[k], 0, 0);

  gpu_buffer ubo_buf(ctx, sizeof ubo, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, memory_use::upload);
  ubo_buf.write(&ubo, sizeof ubo);
  // Host-visible and coherent: written before the submission, read after the fence.
  gpu_buffer probe_buf(ctx, sizeof io, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, memory_use::upload);
  probe_buf.write(&io, sizeof io);

  const compute_pipeline pipeline(
      ctx, probe_shader(),
      {{RTVK_BINDING_CAMERA, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, ubo_buf.get()},
       {RTVK_BINDING_PROBE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, probe_buf.get()}},
      0);
  ctx.submit_and_wait([&](VkCommandBuffer cb) {
    pipeline.bind(cb);
    vkCmdDispatch(cb, 1, 1, 1);
    VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    b.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    b.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                         &b, 0, nullptr, 0, nullptr);
  });
  std::memcpy(&io, probe_buf.read(), sizeof io);
  return io;
}

}  // namespace rtvk::gpu
