#include "parallel.h"

#include <algorithm>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace rtvk {
namespace {

// The first exception of any worker, and the flag that asks the others to stop.
class first_error {
 public:
  void record(std::exception_ptr e) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (!error_) error_ = std::move(e);
    stop_.store(true);
  }
  const std::atomic<bool>& stop() const { return stop_; }
  void rethrow_if_any() const {
    if (error_) std::rethrow_exception(error_);
  }

 private:
  std::mutex mutex_;
  std::exception_ptr error_;       // the first one recorded
  std::atomic<bool> stop_{false};  // set with the first error
};

std::string what_of(std::exception_ptr e) {
  try {
    std::rethrow_exception(std::move(e));
  } catch (const std::exception& x) {
    return x.what();
  } catch (...) {
    return "unknown error";
  }
}

}  // namespace

void run_workers(int workers, const worker_function& work, const thread_starter& start) {
  first_error error;
  auto guarded = [&](int worker) {
    try {
      work(worker, error.stop());
    } catch (...) {
      error.record(std::current_exception());
    }
  };
  std::vector<std::thread> helpers;
  helpers.reserve(std::size_t(std::max(0, workers - 1)));  // no reallocation while threads run
  for (int w = 1; w < workers && !error.stop().load(); ++w) {
    try {
      std::function<void()> body = [&guarded, w] { guarded(w); };
      helpers.push_back(start ? start(std::move(body)) : std::thread(std::move(body)));
    } catch (...) {  // out of threads (std::system_error) or memory: stop, and say which one
      error.record(std::make_exception_ptr(
          std::runtime_error("starting CPU worker thread " + std::to_string(w + 1) + " of " +
                             std::to_string(workers) + ": " + what_of(std::current_exception()))));
    }
  }
  guarded(0);
  for (std::thread& t : helpers)
    if (t.joinable()) t.join();
  error.rethrow_if_any();
}

}  // namespace rtvk
