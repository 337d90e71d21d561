// The GPU's view of the camera: the uniform buffer it received and the rays get_ray makes.
#include <gtest/gtest.h>

#include <cstring>
#include <tuple>

#include "gpu/packing.h"
#include "gpu/probe.h"
#include "gpu_fixture.h"

namespace rtvk {
namespace {

class GpuLayout : public test::GpuTest {};

void expect_near_vec(const glm::vec3& gpu, const vec3& cpu, const char* what) {
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(gpu[k], cpu[k], 1e-6 * (1 + std::abs(cpu[k]))) << what << " component " << k;
}

TEST_F(GpuLayout, UniformBufferArrivesIntactAndGetRayMatchesTheCpu) {
  // (u, v, lens x, lens y): the corners and the center, then two lens samples.
  const std::array<glm::vec4, RTVK_PROBE_POINTS> uv = {
      glm::vec4(0, 0, 0, 0), glm::vec4(1, 0, 0, 0), glm::vec4(0, 1, 0, 0),
      glm::vec4(1, 1, 0.6f, -0.3f), glm::vec4(0.5f, 0.5f, -0.25f, 0.5f)};
  camera_pose posed;
  posed.lookfrom = point3(13, 2, 3);
  posed.lookat = point3(0, 0, 0);
  posed.vfov = 20;
  posed.aperture = 0.1;
  posed.focus_dist = 10;
  for (auto [pose, aspect, width] :
       {std::tuple{camera_pose{}, 16.0 / 9.0, 400}, {camera_pose{}, 2.0, 7}, {posed, 0.37, 333}}) {
    const camera cam(pose, aspect, width);
    const gpu::probe_io io = gpu::run_probe(gpu(), cam, uv);

    // Byte for byte what the host wrote: every std140 offset agrees with the C++ struct.
    const gpu::camera_ubo sent = gpu::to_ubo(cam);
    EXPECT_EQ(io.echo.image_width, std::uint32_t(cam.image_width()));
    EXPECT_EQ(io.echo.image_height, std::uint32_t(cam.image_height()));
    EXPECT_EQ(io.echo.lower_left, sent.lower_left);
    EXPECT_EQ(io.echo.lens_radius, sent.lens_radius);
    EXPECT_EQ(io.echo.lens_u, sent.lens_u);
    EXPECT_EQ(io.echo.lens_v, sent.lens_v);
    // Every byte but the padding, which the shader need not preserve.
    EXPECT_EQ(std::memcmp(&io.echo, &sent, offsetof(gpu::camera_ubo, pad0)), 0);
    EXPECT_EQ(std::memcmp(&io.echo.lower_left, &sent.lower_left, sizeof(gpu::vec3)), 0);
    EXPECT_EQ(std::memcmp(&io.echo.lens_u, &sent.lens_u, sizeof(gpu::vec3)), 0);
    EXPECT_EQ(std::memcmp(&io.echo.lens_v, &sent.lens_v, sizeof(gpu::vec3)), 0);

    for (int k = 0; k < RTVK_PROBE_POINTS; ++k) {
      SCOPED_TRACE("probe point " + std::to_string(k) + ", width " + std::to_string(width));
      const ray r = cam.get_ray(uv[k].x, uv[k].y, glm::dvec2(uv[k].z, uv[k].w));
      expect_near_vec(glm::vec3(io.ray_origin[k]), r.origin(), "origin");
      expect_near_vec(glm::vec3(io.direction[k]), r.direction(), "direction");
    }
  }
}

TEST_F(GpuLayout, ValidationLayerFindingsAreCaughtAndCounted) {
  // The GPU tests' "validation-clean" verdict means something only if a finding is seen: make
  // one on purpose (a zero-sized buffer is invalid usage) and check that it is counted.
  ASSERT_TRUE(gpu().validating());
  const auto before = gpu().validation_messages();
  VkBufferCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  info.size = 0;
  info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  VkBuffer buffer = VK_NULL_HANDLE;
  vkCreateBuffer(gpu().vk(), &info, nullptr, &buffer);
  EXPECT_GT(gpu().validation_messages(), before);
  if (buffer) vkDestroyBuffer(gpu().vk(), buffer, nullptr);
  ctx_.reset();  // this test's own finding must not fail it in TearDown
}

}  // namespace
}  // namespace rtvk

#include "gpu/buffer.h"

namespace rtvk {
namespace {

TEST_F(GpuLayout, SynchronizationValidationCatchesAMissingBarrier) {
  // A fill and then a copy out of the same buffer with no barrier between them: a read-after-write
  // hazard that only synchronization validation sees. It must be reported, or the GPU tests'
  // "validation-clean" says nothing about rtvk's barriers.
  const auto before = gpu().validation_messages();
  {
    const VkBufferUsageFlags usage =
        VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    gpu::gpu_buffer a(gpu(), 256, usage, gpu::memory_use::device_local);
    gpu::gpu_buffer b(gpu(), 256, usage, gpu::memory_use::device_local);
    gpu().submit_and_wait([&](VkCommandBuffer cb) {
      vkCmdFillBuffer(cb, a.get(), 0, VK_WHOLE_SIZE, 7);
      const VkBufferCopy copy{0, 0, 256};
      vkCmdCopyBuffer(cb, a.get(), b.get(), 1, &copy);  // no barrier after the fill
    });
  }  // everything is released before the device goes
  EXPECT_GT(gpu().validation_messages(), before);
  ctx_.reset();  // this test's own finding must not fail it in TearDown
}

}  // namespace
}  // namespace rtvk
