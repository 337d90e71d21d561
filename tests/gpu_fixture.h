#pragma once
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>
#include <string>

#include "ci.h"
#include "context.h"

namespace rtvk::test {

inline constexpr const char* lavapipe_icd = "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json";

// RTVK_TEST_DEVICE: a --device selector for a real device; empty means lavapipe.
inline std::string test_device() {
  const char* d = std::getenv("RTVK_TEST_DEVICE");
  return d ? d : "";
}

// Every GPU test: one validated context per test process. A test fails if the validation layer
// reports any warning or error while it runs. Without a device the test fails in CI and skips
// elsewhere, saying why.
class GpuTest : public ::testing::Test {
 protected:
  void SetUp() override {
    try {
      gpu::gpu_options o;
      o.device = test_device();
      o.validate = true;
      ctx_ = std::make_unique<gpu::gpu_context>(o);
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
};

}  // namespace rtvk::test
