// The CPU renderer's parallel loop: every item once, no more threads than asked for, an error in
// any chunk reaches the caller (never std::terminate); and the interrupt flag worker threads poll
// is shared without a data race, checked in the ThreadSanitizer test program too.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

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

#if !defined(RTVK_WITHOUT_TBB)
TEST(ParallelFor, EveryItemRunsOnceInChunksOfAtMostTheGrain) {
  std::vector<std::atomic<int>> runs(10007);
  std::atomic<bool> oversized{false};
  parallel_for(runs.size(), 4, 64, [&](std::size_t begin, std::size_t end) {
    if (end - begin > 64 || end <= begin) oversized = true;
    for (std::size_t i = begin; i < end; ++i) ++runs[i];
  });
  EXPECT_FALSE(oversized.load());
  for (std::size_t i = 0; i < runs.size(); ++i) ASSERT_EQ(runs[i].load(), 1) << "item " << i;
}

TEST(ParallelFor, NoMoreThreadsThanAskedFor) {
  for (const int threads : {1, 2, 3}) {
    std::atomic<int> running{0}, most{0};
    std::mutex seen_mutex;
    std::set<std::thread::id> seen;
    parallel_for(48, threads, 1, [&](std::size_t, std::size_t) {
      const int now = ++running;
      for (int m = most.load(); now > m && !most.compare_exchange_weak(m, now);) {
      }
      {
        const std::lock_guard<std::mutex> lock(seen_mutex);
        seen.insert(std::this_thread::get_id());
      }
      std::this_thread::sleep_for(1ms);
      --running;
    });
    EXPECT_LE(most.load(), threads);
    EXPECT_LE(int(seen.size()), threads);
    if (threads == 1) {
      EXPECT_EQ(*seen.begin(), std::this_thread::get_id());  // the caller's own
    }
  }
}

TEST(ParallelFor, AChunksErrorCancelsTheRestAndIsRethrownOnTheCallerWithItsType) {
  std::atomic<int> ran{0};
  try {
    parallel_for(20000, 2, 1, [&](std::size_t begin, std::size_t) {
      ++ran;
      if (begin == 0) throw usage_error("chunk 0 failed");
      std::this_thread::sleep_for(50us);
    });
    ADD_FAILURE() << "no exception";
  } catch (const usage_error& e) {  // its own type: the CLI maps it to its own exit status
    EXPECT_STREQ(e.what(), "chunk 0 failed");
  }
  EXPECT_LT(ran.load(), 10000) << "chunks not yet started when one failed still ran";
}

#endif

TEST(InterruptFlag, WorkerThreadsSeeASignalTheMainThreadReceives) {
  const interrupt_guard guard;
  std::atomic<int> saw{0};
  const auto wait_for_signal = [&] {
    EXPECT_TRUE(wait_until([] { return pending_signal() == SIGINT; }));
    ++saw;
  };
  std::vector<std::thread> workers;
  for (int w = 0; w < 3; ++w) workers.emplace_back(wait_for_signal);
  std::raise(SIGINT);  // the handler runs on this thread; the others poll
  wait_for_signal();
  for (std::thread& t : workers) t.join();
  EXPECT_EQ(saw.load(), 4);
}

}  // namespace
}  // namespace rtvk
