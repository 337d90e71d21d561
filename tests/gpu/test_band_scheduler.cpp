// The band scheduler against a fake queue: no Vulkan, a "device" that runs each submission the
// moment it is queued (as fast as a device can, so that the host always finds the newer
// submission finished too) and counts in its status whatever the test tells it to.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <functional>
#include <stdexcept>
#include <vector>

#include "band_scheduler.h"

namespace rtvk::gpu {
namespace {

// Counters with the starved ones set, and with the cut ones set.
render_status starved(std::uint32_t budget) {
  render_status st{};
  st.starved_pixels = 1;
  st.starved_budget = budget;
  return st;
}
render_status cut(std::uint32_t traversals) {
  render_status st{};
  st.cut_traversals = traversals;
  return st;
}

// The status counters a submission leaves: the test's function of the submission and its index.
using fake_device = std::function<render_status(const band_submission&, std::size_t index)>;

class fake_queue : public band_queue {
 public:
  explicit fake_queue(fake_device device = {}) : device_(std::move(device)) {}

  band_ticket submit(const band_submission& s) override {
    const std::size_t index = submitted.size();
    submitted.push_back(s);
    // The device copies its counters into the submission's readback slot.
    readback_.at(s.slot) = device_ ? device_(s, index) : render_status{};
    in_flight_most = std::max(in_flight_most, submitted.size() - waited_through);
    return {submitted.size(), 1};
  }
  void wait(std::uint64_t ticket) override {
    waited.push_back(ticket);
    waited_through = std::max<std::size_t>(waited_through, ticket);
  }
  void wait_all() noexcept override { ++waits_for_all; }
  bool has_timer() const override { return true; }
  double device_seconds(std::uint64_t) const override { return 0.001; }
  render_status status(std::uint32_t slot) override { return readback_.at(slot); }
  std::string device_name() const override { return "the fake device"; }

  std::vector<band_submission> submitted;  // in order
  std::vector<std::uint64_t> waited;       // tickets, in the order waited for
  std::size_t waited_through = 0;          // every ticket up to this one was waited for
  std::size_t in_flight_most = 0;          // submissions queued and not waited for, at most
  int waits_for_all = 0;

 private:
  fake_device device_;
  std::array<render_status, band_slots> readback_{};  // the status readbacks
};

// A scheduler with its own pacer (one sample a submission unless told), over a band of one view,
// on a device known to cut loops (lavapipe's budgets) unless told.
struct scheduler_fixture {
  explicit scheduler_fixture(fake_device device = {}, std::uint32_t fixed_budget = 0,
                             std::function<bool()> cancel = {}, bool loop_limited = true)
      : queue(std::move(device)),
        pace(pacing_for(false, loop_limited), 1, 1, fixed_budget),
        cancelled(std::move(cancel)),
        scheduler(queue, {pace, trace_cost, cuts}, win, 1.0f, cancelled) {}

  void draw() { scheduler.draw(band, {}, &stats); }

  render_window win{0, 0, 1000, 1000, 0, 8};  // 8 samples of a 1000x1000 image
  band_pass band{0, 1, 0, 1000, 0, 1000};     // all of it
  fake_queue queue;
  pacer pace;
  std::uint32_t trace_cost = 1, cuts = 0;
  std::function<bool()> cancelled;
  band_scheduler scheduler;
  render_stats stats;
};

TEST(BandScheduler, KeepsTwoSubmissionsInFlightAndWaitsInOrder) {
  scheduler_fixture f;
  f.draw();
  ASSERT_EQ(f.queue.submitted.size(), 8u);
  for (std::size_t k = 0; k < 8; ++k) {
    const band_submission& s = f.queue.submitted[k];
    EXPECT_EQ(s.from, k);
    EXPECT_EQ(s.to, k + 1);
    EXPECT_EQ(s.first, k == 0);
    EXPECT_EQ(s.last, k == 7);
    EXPECT_EQ(f.queue.waited[k], k + 1);
  }
  EXPECT_EQ(f.queue.in_flight_most, std::size_t(band_slots));
  EXPECT_EQ(f.stats.submissions, 8);
}

TEST(BandScheduler, DrawsUnfinishedPixelsAgainAtTheLastTarget) {
  // The first submission at the last target leaves 3 pixels short of it; the next, none.
  scheduler_fixture f([](const band_submission& s, std::size_t index) {
    render_status st{};
    if (s.last && index == 7) st.unfinished_pixels = 3;
    return st;
  });
  f.draw();
  ASSERT_EQ(f.queue.submitted.size(), 9u);
  EXPECT_EQ(f.queue.submitted[8].from, 8u);
  EXPECT_EQ(f.queue.submitted[8].to, 8u);
  EXPECT_TRUE(f.queue.submitted[8].last);
}

TEST(BandScheduler, StopsWhenNoPixelAdvances) {
  scheduler_fixture f([](const band_submission&, std::size_t) {
    render_status st{};
    st.unfinished_pixels = 1;
    return st;
  });
  EXPECT_THROW(f.draw(), std::runtime_error);
  EXPECT_EQ(f.queue.submitted.size(), 8u + 8u + 16u);  // the samples, then samples + 16 passes
}

TEST(BandScheduler, StarvedSamplesRaiseTheLoopBudget) {
  scheduler_fixture f([](const band_submission& s, std::size_t index) {
    render_status st{};
    if (index < 2) st = starved(s.loop_budget);
    return st;
  });
  f.draw();
  // 2^22 iterations over a million pixels is below the lowest budget, 256; the first
  // submission's starved pixel makes it 1024 for those queued after it was read.
  EXPECT_EQ(f.queue.submitted[1].loop_budget, pacer::first_loop_budget);
  EXPECT_EQ(f.queue.submitted[2].loop_budget, 4 * pacer::first_loop_budget);
}

// Two submissions in flight whose counters differ. The device here is as fast as any: by the
// time the host reads the first's counters, the second has copied its own too. Each must be
// read from its own readback: the first's starved pixel raises the budget, its overflow fails
// the render, though the second's counters are clean.
TEST(BandScheduler, EachSubmissionIsReadFromItsOwnStatusReadback) {
  scheduler_fixture f([](const band_submission& s, std::size_t index) {
    return index == 0 ? starved(s.loop_budget) : render_status{};
  });
  f.draw();
  EXPECT_EQ(f.queue.submitted[0].slot, 0u);
  EXPECT_EQ(f.queue.submitted[1].slot, 1u);
  EXPECT_EQ(f.queue.submitted[2].loop_budget, 4 * pacer::first_loop_budget);
}

TEST(BandScheduler, AnOverflowInTheOlderSubmissionIsNotHiddenByTheNewer) {
  scheduler_fixture f([](const band_submission&, std::size_t index) {
    render_status st{};
    st.overflowed_samples = index == 0 ? 1 : 0;
    return st;
  });
  EXPECT_THROW(f.draw(), sample_overflow_error);
}

TEST(BandScheduler, StarvedAtTheHighestBudgetFails) {
  scheduler_fixture f([](const band_submission& s, std::size_t) { return starved(s.loop_budget); },
                      loop_limited_budget);
  EXPECT_THROW(f.draw(), loop_budget_error);
}

TEST(BandScheduler, CutTraversalsDoubleTheTraceCost) {
  scheduler_fixture f([](const band_submission&, std::size_t index) {
    return cut(index >= 2 ? 5u : 0u);  // counted since the band began
  });
  f.draw();
  EXPECT_EQ(f.trace_cost, 2u);  // one doubling: the count grew once
  EXPECT_EQ(f.stats.cut_traversals, 5u);
}

// On a device not known to cut loops, the first cut holds the budgets to lavapipe's (the probe
// found a limit); only a cut after that doubles the trace cost.
TEST(BandScheduler, ACutOnADeviceWithoutAKnownLimitHoldsItToLavapipesBudget) {
  scheduler_fixture f(
      [](const band_submission&, std::size_t index) { return cut(index >= 2 ? 5u : 0u); }, 0, {},
      false);
  EXPECT_EQ(f.pace.highest_loop_budget(), unlimited_budget);
  f.draw();
  EXPECT_EQ(f.pace.highest_loop_budget(), loop_limited_budget);
  EXPECT_EQ(f.trace_cost, 1u);
  EXPECT_EQ(f.stats.cut_traversals, 5u);
}

TEST(BandScheduler, CancellationWaitsForTheDeviceAndThrows) {
  int polls = 0;
  scheduler_fixture f({}, 0, [&] { return ++polls > 3; });
  EXPECT_THROW(f.draw(), render_cancelled);
  EXPECT_EQ(f.queue.submitted.size(), 3u);
  EXPECT_EQ(f.queue.waits_for_all, 1);
}

}  // namespace
}  // namespace rtvk::gpu
