// The CPU renderer's worker threads: an error in any of them reaches the caller (never
// std::terminate), and the interrupt flag they poll is shared without a data race. Built into
// the ThreadSanitizer test program too, where a race fails the test.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <stdexcept>
#include <system_error>
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
  std::atomic<int> started{0}, finished{0};
  try {
    run_workers(4, [&](int w, const std::atomic<bool>& stop) {
      ++started;
      if (w == 1) throw usage_error("worker 1 failed");
      EXPECT_TRUE(wait_until([&] { return stop.load(); })) << "worker " << w << " never stopped";
      ++finished;
    });
    ADD_FAILURE() << "no exception";
  } catch (const usage_error& e) {  // its own type: the CLI maps it to its own exit status
    EXPECT_STREQ(e.what(), "worker 1 failed");
  }
  // Helpers not yet started when worker 1 failed are never started; every one that was, and the
  // caller, stopped and was joined before the rethrow.
  EXPECT_GE(started.load(), 2);
  EXPECT_EQ(finished.load(), started.load() - 1);
}

TEST(RunWorkers, OnlyTheFirstErrorIsRethrown) {
  EXPECT_THROW(run_workers(3,
                           [&](int w, const std::atomic<bool>& stop) {
                             if (w == 0) {  // fails only after a helper's error is recorded
                               EXPECT_TRUE(wait_until([&] { return stop.load(); }));
                               throw std::logic_error("late");
                             }
                             throw std::runtime_error("early");
                           }),
               std::runtime_error);
}

TEST(RunWorkers, AThreadThatCannotStartIsAnErrorOnceTheStartedOnesStop) {
  std::atomic<int> finished{0};
  int starts = 0;
  const thread_starter out_of_threads = [&](std::function<void()> body) {
    if (++starts == 2)
      throw std::system_error(std::make_error_code(std::errc::resource_unavailable_try_again));
    return std::thread(std::move(body));
  };
  try {
    run_workers(
        4,
        [&](int w, const std::atomic<bool>& stop) {
          EXPECT_TRUE(wait_until([&] { return stop.load(); })) << "worker " << w;
          ++finished;
        },
        out_of_threads);
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "starting CPU worker thread 3 of 4: Resource temporarily unavailable");
  }
  EXPECT_EQ(starts, 2) << "no thread is started after one failed";
  EXPECT_EQ(finished.load(), 2) << "worker 1 and the caller ran, stopped and were joined";
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
