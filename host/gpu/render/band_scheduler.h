#pragma once
// The band scheduler: how the submissions of a band follow one another (two in flight, the
// oldest waited for while the newest runs), what their status counters make of the next ones
// (budgets, trace costs, failures) and how long each should be (pacer.h). It submits through a
// band_queue, so that tests can drive it with a fake queue and no device; the engine's queue
// (band_commands.h) records the Vulkan commands.
#include <chrono>
#include <cstdint>
#include <string>

#include "engine_options.h"
#include "errors.h"
#include "pacer.h"
#include "render_gpu.h"
#include "render_settings.h"
#include "shared_types.h"

namespace rtvk::gpu {

// Submissions in flight at once: gpu_context::submission_slots (band_commands.cpp checks).
inline constexpr std::uint32_t band_slots = 2;

// One band: rows of a group of views, drawn with all their samples before the next. Where it is
// in the whole render, for progress and messages.
struct band_pass {
  std::size_t first_view;          // of the render's views
  std::uint32_t views;             // views in the group (the dispatch's z size)
  std::uint32_t y0, rows;          // image rows the band covers
  std::uint64_t view_rows_before;  // rows of all views drawn before this band
  std::uint64_t view_rows;         // rows of all views in the render
  std::uint64_t pixels() const { return std::uint64_t(views) * rows; }  // times the width
};

// One submission, as the scheduler asks for it: dispatches bringing every pixel of the band
// from `from` up to `to` samples, `step` at a time.
struct band_submission {
  const band_pass* band;
  bool first;                 // the band's first: its sums and status are cleared before
  bool last;                  // at the band's last target: unfinished pixels counted afresh by
                              // the last dispatch, and the readback follows
  std::uint32_t from, to;     // samples per pixel before and after it
  std::uint32_t step;         // samples per dispatch
  std::uint32_t loop_budget;  // render_push::loop_budget
  std::uint32_t trace_cost;   // render_push::trace_cost
  std::uint32_t probe_trips;  // render_push::probe_trips
  std::uint32_t slot;         // the status readback it copies its counters into (< band_slots)
};

// A submission queued: its ticket (what wait and device_seconds take) and its dispatches.
struct band_ticket {
  std::uint64_t ticket;
  std::uint32_t dispatches;
};

// What the scheduler submits through: the engine's device queue, or a test's fake.
class band_queue {
 public:
  virtual ~band_queue() = default;
  // Records and queues one submission; it copies the status counters into readback `s.slot`.
  virtual band_ticket submit(const band_submission& s) = 0;
  // Waits for the submission and all before it (throws on a timeout or a lost device).
  virtual void wait(std::uint64_t ticket) = 0;
  virtual void wait_all() noexcept = 0;  // for clean-up on errors
  virtual bool has_timer() const = 0;    // device times are measured
  // A finished submission's device time, seconds (0 without a timer).
  virtual double device_seconds(std::uint64_t ticket) const = 0;
  // The status counters in readback `slot`, once the submission that copied them there is
  // waited for. Each submission in flight has its own slot: a newer one, running while the host
  // reads, writes the other.
  virtual render_status status(std::uint32_t slot) = 0;
  virtual std::string device_name() const = 0;  // for messages
};

// What the scheduler changes that outlives one render: the pacer's sizes and budgets, and the
// hardware paths' trace cost and simulated cuts (gpu_render_options).
struct band_carry {
  pacer& pace;
  std::uint32_t& trace_cost;      // render_push::trace_cost, doubled whenever a traversal was cut
  std::uint32_t& simulated_cuts;  // gpu_render_options::simulated_cuts still to make
};

// Draws bands. Each submission brings every pixel up by `batch` samples, in dispatches of
// `per_dispatch` samples each; two submissions are in flight at once, so the device starts the
// next while the host waits for the last. Both sizes grow from one to what pacing_for asks of the
// device: on a GPU, submissions of about a tenth of a second (long enough to keep the device
// busy, short enough for progress, interruption and the fence timeout) and dispatches of a few
// milliseconds of device time. Pixels whose loop budget ran out go on in the next dispatch; once
// the last target is asked for, the scheduler waits, and submits again until no pixel is
// unfinished.
class band_scheduler {
 public:
  // `win`: the region and samples of every view; `sample_limit`: render_push::sample_limit, for
  // the overflow's message; `cancelled`: polled before every submission (may be empty).
  band_scheduler(band_queue& queue, const band_carry& carry, const render_window& win,
                 float sample_limit, const std::function<bool()>& cancelled)
      : queue_(queue),
        carry_(carry),
        win_(win),
        sample_limit_(sample_limit),
        cancelled_(cancelled) {}

  // Every sample of the band; `progress` is called with samples done over all passes.
  void draw(const band_pass& b, const sample_progress& progress, render_stats* stats);
  // The counters of the band's last submission (its dropped samples and rays, for all of it).
  const render_status& last_status() const { return status_; }

 private:
  // A submission in flight: what it asked of the pixels, and when.
  struct in_flight {
    band_ticket queued;                           // its ticket and dispatches
    std::uint32_t slot;                           // its status readback
    std::uint32_t target;                         // samples every pixel has once it is done...
    bool complete;                                // ...unless some are unfinished (final target)
    std::chrono::steady_clock::time_point since;  // when it was submitted
  };
  in_flight submit(const band_pass& b, bool first, std::uint32_t from, std::uint32_t to);
  void finish(const in_flight& f, render_stats* stats);
  render_cancelled cancelled(const band_pass& b, std::uint32_t done) const;
  int progress_value(const band_pass& b, std::uint32_t target) const;

  band_queue& queue_;
  band_carry carry_;
  const render_window& win_;                // region and sample range of every view
  float sample_limit_;                      // render_push::sample_limit
  const std::function<bool()>& cancelled_;  // engine_options::cancelled
  render_status status_{};                  // as the last finished submission left it
  std::uint32_t cuts_seen_ = 0;  // render_status::cut_traversals of the band, as last read
  std::uint32_t next_slot_ = 0;  // the status readback of the next submission
};

}  // namespace rtvk::gpu
