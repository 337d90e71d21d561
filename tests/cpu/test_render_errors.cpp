// Failures inside the CPU renderer's worker threads end the render with the failure, on the
// calling thread, with its own type and message: the process is never terminated by a thread.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

#include "errors.h"
#include "render_helpers.h"

namespace rtvk {
namespace {

TEST(RenderCpuErrors, AFailureInAWorkerThreadReachesTheCaller) {
  const scene s = test::small_scene("materials", 64, 2);
  const camera cam = test::scene_camera(s);
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<bool> polled_elsewhere{false};
  engine_options engine;
  engine.threads = 4;
  // The cancellation poll runs before every chunk: a natural place to inject a failure into a
  // thread that is not the caller. The caller's polls wait (10 s at most) until another thread
  // has polled, so the failure happens there however the chunks happen to be shared out.
  engine.cancelled = [&] {
    if (std::this_thread::get_id() != caller) {
      polled_elsewhere = true;
      throw usage_error("injected failure in a worker");
    }
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (!polled_elsewhere && std::chrono::steady_clock::now() < end)
      std::this_thread::sleep_for(std::chrono::microseconds(100));
    return false;
  };
  try {
    render_cpu(cam, s, s.render, {}, engine);
    ADD_FAILURE() << "the render finished despite the failure";
  } catch (const usage_error& e) {
    EXPECT_STREQ(e.what(), "injected failure in a worker");
  }
}

}  // namespace
}  // namespace rtvk
