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
  const std::array<glm::vec2, RTVK_PROBE_POINTS> uv = {
      glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(0, 1), glm::vec2(1, 1), glm::vec2(0.5f, 0.5f)};
  for (auto [aspect, width] : {std::tuple{16.0 / 9.0, 400}, {2.0, 7}, {0.37, 333}}) {
    const camera cam(aspect, width);
    const gpu::probe_io io = gpu::run_probe(gpu(), cam, uv);

    // Byte for byte what the host wrote: every std140 offset agrees with the C++ struct.
    const gpu::camera_ubo sent = gpu::to_ubo(cam);
    EXPECT_EQ(io.echo.image_width, std::uint32_t(cam.image_width()));
    EXPECT_EQ(io.echo.image_height, std::uint32_t(cam.image_height()));
    EXPECT_EQ(io.echo.lower_left, sent.lower_left);
    EXPECT_EQ(std::memcmp(&io.echo, &sent, offsetof(gpu::camera_ubo, pad0)), 0);
    EXPECT_EQ(std::memcmp(&io.echo.lower_left, &sent.lower_left, sizeof(gpu::vec3)), 0);

    expect_near_vec(glm::vec3(io.ray_origin), cam.get_ray(0, 0).origin(), "origin");
    for (int k = 0; k < RTVK_PROBE_POINTS; ++k) {
      SCOPED_TRACE("probe point " + std::to_string(k) + ", width " + std::to_string(width));
      expect_near_vec(glm::vec3(io.direction[k]), cam.get_ray(uv[k].x, uv[k].y).direction(),
                      "direction");
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
