#pragma once
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <memory>
#include <string>

#include "ci.h"
#include "context.h"
#include "software_device.h"

namespace rtvk::test {

// The options every GPU test's context is made with: the device under test, validation on, and
// a fence timeout long enough for a cold compile. lavapipe compiles a pipeline's shaders when it
// first runs them, inside the submission: a variant Mesa's cache does not hold yet
// (tests/test_main.cpp) takes Mesa 25 up to a minute, several on a loaded machine
// (GpuLimits.AnImageTextureAboveTheStorageRangeIsRefusedNamingIt once failed at the default
// 120 s so, on its own context), the hardware paths' larger shaders longer still. Tests that make
// a context of their own (lowered limits) start from these.
inline gpu::gpu_options gpu_test_options(bool ray_tracing = false) {
  gpu::gpu_options o;
  o.device = device_under_test();
  o.validate = true;
  o.ray_tracing = ray_tracing;
  o.fence_timeout = std::chrono::minutes(10);
  return o;
}

// Every GPU test: one validated context per test process. A test fails if the validation layer
// reports any warning or error while it runs. Without the device the test fails in CI and skips
// elsewhere, saying what it looked for and what the loader offered.
class GpuTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (test_device().empty() && !software_device().found) {
      if (in_ci())
        FAIL() << "no software Vulkan device in CI (GPU tests must run): "
               << software_device().failure;
      GTEST_SKIP() << "no software Vulkan device, GPU test not run: " << software_device().failure;
    }
    try {
      ctx_ = std::make_unique<gpu::gpu_context>(gpu_test_options(ray_tracing_));
    } catch (const std::exception& e) {
      if (in_ci()) FAIL() << "no Vulkan device in CI (GPU tests must run): " << e.what();
      GTEST_SKIP() << "no Vulkan device, GPU test not run: " << e.what();
    }
  }
  void TearDown() override {
    if (ctx_) {
      EXPECT_EQ(ctx_->validation_messages(), 0u) << "validation messages during this test";
    }
    ctx_.reset();
  }
  gpu::gpu_context& gpu() { return *ctx_; }

  std::unique_ptr<gpu::gpu_context> ctx_;  // fresh per test
  bool ray_tracing_ = false;  // made with gpu_options::ray_tracing (set by a derived fixture)
};

}  // namespace rtvk::test
