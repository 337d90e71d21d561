// The CPU renderer's worker threads: an error in any of them reaches the caller (never
// std::terminate), and the interrupt flag they poll is shared without a data race. Built into
// the ThreadSanitizer test program too, where a race fails the test.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <stdexcept>
#include <thread>

#include "errors.h"
#include "interrupt.h"
#include "parallel.h"

namespace rtvk {
namespace {

using namespace std::chrono_literals;

// Waits until `done` says so, at most 10 s, so a broken stop flag fails instead of hanging.
template <typename Done>
bool wait_until(Done done) {
  const auto end = std::chrono::steady_clock::now() + 10s;
  while (!done()) {
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(100us);
  }
  return true;
}

TEST(RunWorkers, EveryWorkerRunsOnce) {
  std::atomic<int> mask{0};
  run_workers(5, [&](int w, const std::atomic<bool>&) { mask.fetch_or(1 << w); });
  EXPECT_EQ(mask.load(), 0b11111);
}

TEST(RunWorkers, AWorkersErrorStopsTheOthersAndIsRethrownOnTheCaller) {
  std::atomic<int> finished{0};
  try {
    run_workers(4, [&](int w, const std::atomic<bool>& stop) {
      if (w == 2) throw usage_error("worker 2 failed");
      EXPECT_TRUE(wait_until([&] { return stop.load(); })) << "worker " << w << " never stopped";
      ++finished;
    });
    ADD_FAILURE() << "no exception";
  } catch (const usage_error& e) {  // its own type: the CLI maps it to its own exit status
    EXPECT_STREQ(e.what(), "worker 2 failed");
  }
  EXPECT_EQ(finished.load(), 3) << "every other worker stopped and was joined before the rethrow";
}

TEST(RunWorkers, OnlyTheFirstErrorIsRethrown) {
  std::atomic<int> thrown{0};
  EXPECT_THROW(run_workers(3,
                           [&](int w, const std::atomic<bool>&) {
                             if (w == 0) {
                               // after a helper's error (which may keep the last helper
                               // from starting at all)
                               EXPECT_TRUE(wait_until([&] { return thrown.load() >= 1; }));
                               throw std::logic_error("late");
                             }
                             ++thrown;
                             throw std::runtime_error("early");
                           }),
               std::runtime_error);
}

TEST(InterruptFlag, WorkerThreadsSeeASignalTheMainThreadReceives) {
  const interrupt_guard guard;
  std::atomic<int> saw{0};
  run_workers(4, [&](int w, const std::atomic<bool>&) {
    if (w == 0) std::raise(SIGINT);  // the handler runs on this thread; the others poll
    EXPECT_TRUE(wait_until([] { return pending_signal() == SIGINT; })) << "worker " << w;
    ++saw;
  });
  EXPECT_EQ(saw.load(), 4);
}

}  // namespace
}  // namespace rtvk
