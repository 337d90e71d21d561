#pragma once
#include <atomic>
#include <functional>

namespace rtvk {

// Runs work(worker, stop) on `workers` threads, the calling thread being worker 0, and returns
// once every one has returned. When a worker throws (or a thread cannot be started), `stop` is
// set so the others can end early, and after all of them have stopped the first exception is
// rethrown here, on the calling thread: an error in a worker is the caller's error, with its own
// type and message, never std::terminate.
void run_workers(int workers,
                 const std::function<void(int worker, const std::atomic<bool>& stop)>& work);

}  // namespace rtvk
