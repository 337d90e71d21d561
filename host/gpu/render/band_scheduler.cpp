#include "band_scheduler.h"

#include <algorithm>
#include <deque>
#include <stdexcept>

#include "elapsed.h"
#include "format.h"

namespace rtvk::gpu {
namespace {

// The most render_push::trace_cost grows to (gpu_engine.cpp's first_trace_cost doubled).
constexpr std::uint32_t max_trace_cost = 1u << 14;

// A sample needed more than the largest loop budget: the render fails rather than show it.
loop_budget_error overrun(const render_status& st, std::uint32_t budget, const std::string& dev) {
  const std::string why =
      budget == loop_limited_budget
          ? " (its driver stops loops early, as lavapipe silently does at 65,535, so rtvk stops "
            "first and writes no image)"
          : " (the most one invocation may run here; no image was written)";
  return loop_budget_error(std::to_string(st.starved_pixels) + " pixel samples needed more than " +
                           std::to_string(budget) + " loop iterations on " + dev + why +
                           ": lower --depth, use fewer objects, --accel bvh or --sampling plain");
}

// Samples past the exact sums' limit: the render fails rather than clamp them into bias.
sample_overflow_error overflow(const render_status& st, float limit) {
  return sample_overflow_error(std::to_string(st.overflowed_samples) +
                               " samples had a channel above " + format_number(limit) +
                               ", more than rtvk's exact sums hold; no image was written");
}

}  // namespace

void band_scheduler::draw(const band_pass& b, const sample_progress& progress,
                          render_stats* stats) {
  const std::uint32_t samples = std::uint32_t(win_.samples());
  std::deque<in_flight> pending;
  std::uint32_t target = 0;        // asked of every pixel so far
  std::uint32_t final_passes = 0;  // completed submissions asking for the last target
  bool first = true;
  // Each pass at the last target moves every unfinished pixel on by a sample at least, unless
  // the pixel starved and the budget grows (a few times at most): more passes than that would
  // mean none moves any more.
  const std::uint32_t most_final_passes = samples + 16;
  cuts_seen_ = 0;  // the band's status is cleared
  for (;;) {
    if (cancelled_ && cancelled_()) {
      queue_.wait_all();
      throw cancelled(b, target);
    }
    const std::uint32_t from = target;
    target = std::min(samples, target + carry_.pace.samples_per_submission());
    pending.push_back(submit(b, first, from, target));
    first = false;
    // Wait for the oldest while the newest runs; at the last target, for all of them.
    while (!pending.empty() && (pending.size() == band_slots || target == samples)) {
      const in_flight done = pending.front();
      pending.pop_front();
      finish(done, stats);
      if (progress) progress(progress_value(b, done.target));
      if (done.complete && status_.unfinished_pixels == 0) return;
      if (done.complete && ++final_passes > most_final_passes)
        throw std::runtime_error(
            "the GPU render stopped advancing: " + std::to_string(status_.unfinished_pixels) +
            " pixels still unfinished after " + std::to_string(final_passes) + " passes on " +
            queue_.device_name());
    }
  }
}

render_cancelled band_scheduler::cancelled(const band_pass& b, std::uint32_t done) const {
  return render_cancelled(
      "stopped after " + std::to_string(done) + " of " + std::to_string(win_.samples()) +
      " samples per pixel of rows " + std::to_string(b.y0) + " to " +
      std::to_string(b.y0 + b.rows - 1) + " of view " + std::to_string(b.first_view + 1) +
      (b.views > 1 ? " to " + std::to_string(b.first_view + b.views) : std::string()) + " of " +
      std::to_string(b.view_rows / std::uint64_t(win_.height)));
}

// Samples per pixel of the whole render done, as if every pixel had the same share.
int band_scheduler::progress_value(const band_pass& b, std::uint32_t target) const {
  const std::uint64_t done =
      b.view_rows_before * std::uint64_t(win_.samples()) + b.pixels() * target;
  return int(done / b.view_rows);
}

band_scheduler::in_flight band_scheduler::submit(const band_pass& b, bool first, std::uint32_t from,
                                                 std::uint32_t to) {
  band_submission s{};
  s.band = &b;
  s.first = first;
  s.last = to == std::uint32_t(win_.samples());
  s.from = from;
  s.to = to;
  s.step = carry_.pace.samples_per_dispatch();
  s.loop_budget = carry_.pace.loop_budget(std::uint64_t(win_.width) * b.pixels());
  s.trace_cost = carry_.trace_cost;
  s.probe_trips = 2;
  // In turn: the submissions in flight (band_slots at most, waited for in order) never share one.
  s.slot = next_slot_;
  next_slot_ = (next_slot_ + 1) % band_slots;
  if (carry_.simulated_cuts > 0) {
    --carry_.simulated_cuts;
    s.probe_trips = 3;  // limit_was_hit: a 3-trip loop is not the 2-trip one it expects
  }
  return {queue_.submit(s), s.slot, to, s.last, std::chrono::steady_clock::now()};
}

// After the submission is done: device time, overruns, and the sizes of the next ones.
void band_scheduler::finish(const in_flight& f, render_stats* stats) {
  queue_.wait(f.queued.ticket);
  const double device_seconds = queue_.device_seconds(f.queued.ticket);
  const double wall = seconds_since(f.since);
  if (stats) {
    ++stats->submissions;
    stats->gpu_seconds += device_seconds;
  }
  status_ = queue_.status(f.slot);
  // A sample that did not fit its budget is drawn again under a larger one; one that did not
  // fit the largest fails the render.
  if (status_.starved_pixels > 0 && !carry_.pace.starved(status_.starved_budget))
    throw overrun(status_, status_.starved_budget, queue_.device_name());
  // The driver's loop limit cut some invocation short: those pixels kept nothing of it and go on
  // in the next pass. On a device not known to have a limit, under lavapipe's budget from now
  // on; on one held to it already, its own traversal's trips were what passed the limit, and
  // each ray counts twice as many iterations.
  // (The band's status counts them since its start: only the new ones count here.)
  if (status_.cut_traversals > cuts_seen_) {
    if (!carry_.pace.loop_limit_found())
      carry_.trace_cost = std::min(carry_.trace_cost * 2, max_trace_cost);
    if (stats) stats->cut_traversals += status_.cut_traversals - cuts_seen_;
    cuts_seen_ = status_.cut_traversals;
  }
  if (status_.overflowed_samples > 0) throw overflow(status_, sample_limit_);
  // Device time where there is a timer: the wall time includes waiting behind the other
  // submission in flight.
  carry_.pace.measured(queue_.has_timer() ? device_seconds : wall, f.queued.dispatches);
}

}  // namespace rtvk::gpu
