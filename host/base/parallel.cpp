#include "parallel.h"

#include "errors.h"

#include <algorithm>
#include <atomic>
#include <string>
#include <thread>

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/partitioner.h>
#include <oneapi/tbb/task_arena.h>

namespace rtvk {

void run_in_arena(int threads, const std::function<void()>& f) {
  // An arena of the asked-for size: --threads caps rtvk's concurrency, not TBB's global pool.
  // More threads than cores are allowed when asked for (TBB would otherwise refuse, with a
  // warning on stderr).
  const int cores = tbb::this_task_arena::max_concurrency();
  const tbb::global_control allow(tbb::global_control::max_allowed_parallelism,
                                  std::size_t(std::max(threads, cores)));
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute(f);
}

void parallel_for(std::size_t count, int threads, std::size_t grain, const chunk_function& body) {
  if (count == 0) return;
  run_in_arena(threads, [&] {
    // simple_partitioner: chunks of at most `grain`, so progress and cancellation stay fine
    // grained however many threads there are.
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, count, std::max<std::size_t>(grain, 1)),
        [&](const tbb::blocked_range<std::size_t>& r) { body(r.begin(), r.end()); },
        tbb::simple_partitioner());
  });
}

void parallel_pixels(int width, int height, int threads, const std::function<bool()>& cancelled,
                     const std::function<void(int rows_done)>& progress,
                     const chunk_function& body) {
  const std::size_t w = std::size_t(width), pixels = w * std::size_t(height);
  std::atomic<std::size_t> done{0};
  const std::thread::id caller = std::this_thread::get_id();
  parallel_for(pixels, threads, 256, [&](std::size_t begin, std::size_t end) {
    if (cancelled && cancelled()) return;  // the rows left stay undone
    body(begin, end);
    const std::size_t now = done.fetch_add(end - begin) + (end - begin);
    if (progress && std::this_thread::get_id() == caller) progress(int(now / w));
  });
  if (done.load() < pixels)
    throw render_cancelled("stopped after " + std::to_string(done.load() / w) + " of " +
                           std::to_string(height) + " rows");
}

}  // namespace rtvk
