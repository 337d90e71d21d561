// Failures inside the CPU renderer's worker threads end the render with the failure, on the
// calling thread, with its own type and message: the process is never terminated by a thread.
#include <gtest/gtest.h>

#include <atomic>
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
  std::atomic<int> polls_elsewhere{0};
  engine_options engine;
  engine.threads = 4;
  // The cancellation poll runs on every worker: a natural place to inject a failure into one
  // that is not the caller.
  engine.cancelled = [&] {
    if (std::this_thread::get_id() != caller && ++polls_elsewhere == 3)
      throw usage_error("injected failure in a worker");
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
