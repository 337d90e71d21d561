#pragma once
#include <cstddef>
#include <functional>

namespace rtvk {

// What parallel_for runs: the items [begin, end) of the range.
using chunk_function = std::function<void(std::size_t begin, std::size_t end)>;

// Runs body over the items [0, count), in chunks of at most `grain` items (and
// more than half that, where there are that many), on at
// most `threads` threads (0: one per core) with oneTBB's work stealing, so chunks that take
// longer than others (a sky row beside a glass sphere) even out at any image size. Returns when
// every chunk has run. When a chunk throws, chunks not yet started are cancelled and, once the
// running ones have returned, the first exception is rethrown here with its own type and
// message, never std::terminate.
void parallel_for(std::size_t count, int threads, std::size_t grain, const chunk_function& body);

// A render's pixels [0, width * height) in reading order, in chunks of 256 (enough work to
// amortize a task, few enough that every thread stays busy to the end and progress moves
// smoothly) on parallel_for; `body(begin, end)` draws a chunk. `cancelled` is polled before each
// chunk (those not begun once it says yes stay undone), and `progress` gets the rows done so far
// from the calling thread, which draws chunks too. Both may be empty. Throws render_cancelled
// saying how far the render got when it was cancelled.
void parallel_pixels(int width, int height, int threads, const std::function<bool()>& cancelled,
                     const std::function<void(int rows_done)>& progress,
                     const chunk_function& body);

// Runs f, and any oneTBB algorithm it starts, on at most `threads` threads (0: one per core).
void run_in_arena(int threads, const std::function<void()>& f);

}  // namespace rtvk
