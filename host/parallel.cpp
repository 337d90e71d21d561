#include "parallel.h"

#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
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

}  // namespace

void run_workers(int workers,
                 const std::function<void(int worker, const std::atomic<bool>& stop)>& work) {
  first_error error;
  auto guarded = [&](int worker) {
    try {
      work(worker, error.stop());
    } catch (...) {
      error.record(std::current_exception());
    }
  };
  std::vector<std::thread> helpers;
  for (int w = 1; w < workers && !error.stop().load(); ++w) {
    try {
      helpers.emplace_back(guarded, w);
    } catch (const std::system_error& e) {  // out of threads: stop, and say which one failed
      error.record(std::make_exception_ptr(
          std::runtime_error("starting CPU worker thread " + std::to_string(w + 1) + " of " +
                             std::to_string(workers) + ": " + e.what())));
    }
  }
  guarded(0);
  for (std::thread& t : helpers) t.join();
  error.rethrow_if_any();
}

}  // namespace rtvk
