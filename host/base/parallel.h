#pragma once
#include <atomic>
#include <functional>
#include <thread>

namespace rtvk {

// What work() gets: its worker number (0 is the calling thread) and the flag that asks it to
// stop early because another worker failed.
using worker_function = std::function<void(int worker, const std::atomic<bool>& stop)>;

// Starts one helper thread running `body`. The default is std::thread's constructor; tests pass
// one that fails, as the system does when it is out of threads.
using thread_starter = std::function<std::thread(std::function<void()> body)>;

// Runs work(worker, stop) on `workers` threads, the calling thread being worker 0, and returns
// once every one has returned. When a worker throws (or a thread cannot be started), `stop` is
// set so the others can end early, and after all of them have stopped the first exception is
// rethrown here, on the calling thread: an error in a worker is the caller's error, with its own
// type and message, never std::terminate.
void run_workers(int workers, const worker_function& work, const thread_starter& start = {});

}  // namespace rtvk
